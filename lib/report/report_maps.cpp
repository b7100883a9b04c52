// The temperature maps: every snapshot of the field on one colour scale,
// the full ring (output.full_ring) or a window around OA's pipe.
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>
#include <numbers>

#include "geometry/layout.hpp"
#include "particles/parallel.hpp"
#include "report/field_map.hpp"
#include "report/flow_arrows.hpp"
#include "report/nice_scale.hpp"
#include "report/report_sections.hpp"
#include "geometry/interface_planes.hpp"

namespace frostwall::report::detail {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

// The square a shaft's maps show: the whole ring, or a window around OA's
// pipe wide enough for the neighbouring pipes and the wall; `where` says
// which, for the note.
MapWindow map_window(bool full_ring, double ring, double inner, const std::vector<geometry::Pipe2>& pipes,
                     double domain_radius, std::string& where) {
  MapWindow window;
  window.pixels = 400;
  if (full_ring || ring == 0.0) {
    double R = ring > 0 ? std::max(1.4 * ring, ring + 1.5) : 0.5 * domain_radius;
    if (domain_radius > 0) R = std::min(R, domain_radius);
    window.x0 = window.y0 = -R;
    window.size = 2 * R;
    where = "the whole ring";
    return window;
  }
  const auto planes = geometry::interface_planes(pipes);
  const double mid = 0.5 * (ring + inner), gap = std::abs(planes.OB - planes.OA) * 2 * planes.ring_radius;
  const double half = std::max(1.5 * gap, 0.5 * (ring - inner) + 1.5);
  window.x0 = mid * std::cos(planes.OA) - half;
  window.y0 = mid * std::sin(planes.OA) - half;
  window.size = 2 * half;
  where = "a window around the pipe on OA";
  return window;
}

// The pipes of the recorded project and what the maps draw over the field
// (pipe discs, the excavation, the domain's edge), with the pipe ring's
// outer and inner radius; without a project, the wall's extent on OA.
struct ShaftScene {
  std::vector<geometry::Pipe2> pipes;
  MapOverlay overlay;
  double ring = 0.0, inner = std::numeric_limits<double>::infinity();
};

ShaftScene shaft_scene(const RunRecord& run) {
  ShaftScene scene;
  auto& pipes = scene.pipes;
  auto& overlay = scene.overlay;
  if (run.project)
    if (const auto* s = std::get_if<project::ShaftSection>(&run.project->geometry)) {
      pipes = geometry::pipe_positions(s->layout);
      for (const auto& p : pipes) overlay.pipes.push_back({p.x, p.y, 0.5 * s->pipe.diameter});
      overlay.excavation_radius = s->shaft.excavation_radius.value_or(0.0);
      overlay.domain_radius = s->outer_radius;
    }
  double& ring = scene.ring;
  double& inner = scene.inner;
  for (const auto& p : pipes)
    ring = std::max(ring, std::hypot(p.x, p.y)), inner = std::min(inner, std::hypot(p.x, p.y));
  if (ring == 0.0) {  // no project recorded: the wall's extent tells where to look
    for (const auto& w : run.summary["wall"])
      if (w["OA"]["outer"].is_number()) ring = std::max(ring, w["OA"]["outer"].get<double>());
    inner = ring;
  }
  return scene;
}

// One colour scale over every snapshot's free particles and the pipe
// walls' own temperatures (the files hold no particle beyond a wall, whose
// mirrored values would stretch the scale).
ColourScale shaft_temperature_scale(const RunRecord& run, const std::vector<FieldSnapshot>& fields) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& f : fields)
    for (std::size_t i = 0; i < f.temperature.size(); ++i)
      if (f.boundary[i] < 0) lo = std::min(lo, f.temperature[i]), hi = std::max(hi, f.temperature[i]);
  if (run.project)
    if (const auto* s = std::get_if<project::ShaftSection>(&run.project->geometry))
      for (const auto& [t, T] : s->pipe.temperature.points)
        if (t <= run.project->time.end) lo = std::min(lo, T), hi = std::max(hi, T);
  const NiceScale ends = nice_scale(lo, hi, 10);  // ends at a round 5 or 10, not far beyond the data
  return ColourScale(ends.lo, ends.hi, run.freezing_point());
}

// The frozen front of each snapshot and whether it is the whole ring's.
// The front files are listed in summary.json in snapshot order. The whole
// ring's curves when the run wrote them (closed across the wedge sides);
// else the wedge's, copied around by the map.
struct Fronts {
  std::vector<std::vector<post::Polyline>> curves;
  std::vector<char> whole;
};

Fronts read_fronts(const RunRecord& run, std::size_t snapshots) {
  const auto& fronts = run.summary.value("interface", json::array());
  Fronts out{std::vector<std::vector<post::Polyline>>(snapshots), std::vector<char>(snapshots, 0)};
  for (std::size_t k = 0; k < snapshots && k < fronts.size(); ++k)
    for (const char* key : {"full_ring_file", "file"})
      if (fronts[k].contains(key) && fs::exists(run.dir / fronts[k][key].get<std::string>())) {
        out.curves[k] = read_polylines(run.dir / fronts[k][key].get<std::string>());
        out.whole[k] = std::string(key) == "full_ring_file";
        break;
      }
  return out;
}

// A plain geometry's maps, or none for a solid (its temperature is drawn
// beside its displacement and damage) or a porous plate whose files hold
// its solid (the frost section draws it).
void add_maps_of_plain_run(const RunRecord& run, json& view) {
  view["show_maps_note"] = false;
  if (run.mechanics()) return;
  if (run.frost())
    if (const auto files = read_pvd(run.dir / "field.pvd");
        !files.empty() && !read_solid(run.dir / files.front().file).damage.empty())
      return;
  add_plain_maps(run, view);
}

}  // namespace

void add_maps(const RunRecord& run, json& view) {
  view["has_maps"] = false;
  view["maps"] = json::array();
  view["colour_bar_svg"] = "";
  view["maps_note"] = "";
  view["show_maps_note"] = true;
  if (!run.shaft() || !run.summary.contains(keys::wedge)) {
    add_maps_of_plain_run(run, view);
    return;
  }
  const auto snapshots = read_pvd(run.dir / "field.pvd");
  if (snapshots.empty()) {
    view["maps_note"] = "No VTK snapshots in this directory (output.vtk is off), so no maps.";
    return;
  }
  const auto& facts = run.summary[keys::run];
  const double spacing = facts.value(keys::spacing, 0.0), h = smoothing_length(facts);
  const std::string kernel = facts.value("kernel", "wendland_c2");
  const WedgeSymmetry symmetry = wedge_of(run.summary);
  const ShaftScene scene = shaft_scene(run);
  const MapOverlay& overlay = scene.overlay;

  // Read every snapshot first: one colour scale for all of them.
  std::vector<FieldSnapshot> fields;
  for (const auto& s : snapshots) fields.push_back(read_field(run.dir / s.file));
  const ColourScale colours = shaft_temperature_scale(run, fields);

  const bool full_ring = run.project ? run.project->output.full_ring : fs::exists(run.dir / "ring.pvd");
  std::string where;
  const MapWindow window = map_window(full_ring, scene.ring, scene.inner, scene.pipes, overlay.domain_radius, where);
  const FieldMap map(fields.front(), symmetry, kernel, h, spacing, window, overlay.domain_radius);

  // The curves and arrows of every snapshot first (file reads), then the
  // maps drawn and encoded on all threads, one snapshot each.
  const Fronts fronts = read_fronts(run, snapshots.size());
  std::vector<MapOverlay> overlays(snapshots.size(), overlay);
  for (std::size_t k = 0; k < snapshots.size(); ++k)
    overlays[k].arrows = flow_arrows(fields[k], symmetry, window, overlay.domain_radius);
  // Sinking: the lining's inner face once it is placed.
  json e = run.summary.value(keys::excavation, json::object());
  for (const auto& section : e.value("sections", json::array()))  // a layered shaft: the governing layer's
    if (section.value("name", std::string()) == run.summary.value(keys::governing_layer, std::string())) e = section;
  if (e.contains("lining_day"))
    for (std::size_t k = 0; k < snapshots.size(); ++k)
      if (snapshots[k].time >= e["lining_day"].get<double>() - 1e-9)
        overlays[k].lining_radius = e["lining_inner_radius"].get<double>();
  std::vector<std::string> html(snapshots.size());
  particles::for_each_item(snapshots.size(), [&](std::size_t k) {
    html[k] = map.html(fields[k].temperature, colours, fronts.curves[k], fronts.whole[k] != 0, overlays[k],
                       fmt::format("day {:g}", snapshots[k].time));
  });
  json maps = json::array();
  for (std::size_t k = 0; k < snapshots.size(); ++k)
    maps.push_back(
        {{"html", std::move(html[k])},
         {"caption",
          fmt::format("Temperature on day {:g}; black line: frozen front (liquid fraction 0.5){}.", snapshots[k].time,
                      overlays[k].arrows.empty()
                          ? ""
                          : "; white arrows: the groundwater's Darcy flux (length to scale on this map)")}});
  view["maps"] = maps;
  view["has_maps"] = true;
  view["colour_bar_svg"] = colours.colour_bar_svg(520);
  view["maps_note"] = fmt::format(
      "The field of each snapshot resampled from the particles (SPH interpolation) and shown over {}; "
      "the simulated wedge is copied around by its mirror symmetry. Pipes are black dots, the dashed circle "
      "is the excavation. Colours turn from blue to red at the freezing point ({} °C).",
      where, number(run.freezing_point(), 1));
}

}  // namespace frostwall::report::detail
