// The temperature maps of a plain geometry (a verification problem, a
// plate): every snapshot drawn on the particles' own triangles, linear
// within each (what ParaView shows of the VTK cells), on one colour scale,
// with the frozen front where one formed.
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>

#include "report/cloud_raster.hpp"
#include "report/field_map.hpp"
#include "report/nice_scale.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"

namespace frostwall::report::detail {

using nlohmann::json;
namespace fs = std::filesystem;

ColourScale temperature_scale(const std::vector<std::vector<double>>& snapshots, double freezing_point) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& T : snapshots)
    for (double v : T)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  if (!std::isfinite(lo)) lo = hi = freezing_point;
  const NiceScale ends = nice_scale(lo, hi, 10);
  return ColourScale(ends.lo, ends.hi, freezing_point);
}

double triangle_edge(const json& facts) {
  const double spacing = facts.value(keys::spacing, 0.0);
  const double coarsest = facts.value("coarsest_spacing", spacing);
  if (!(spacing > 0.0)) throw std::runtime_error("summary.json: run.spacing is missing; it is needed to draw the maps");
  // A lattice's diagonals are 1.41 spacings; a hole's slivers are longer.
  return 2.5 * std::max(spacing, coarsest);
}

void add_plain_maps(const RunRecord& run, json& view) {
  const auto snapshots = read_pvd(run.dir / "field.pvd");
  view["show_maps_note"] = true;
  if (snapshots.empty()) {
    view["maps_note"] = "No VTK snapshots in this directory (output.vtk is off), so no maps.";
    return;
  }
  const json facts = run.summary.value(keys::run, json::object());
  // The free particles of each snapshot (fixed ones beyond a face, where
  // the files have them, hold extrapolated values).
  std::vector<particles::Vec<2>> points;
  std::vector<std::vector<double>> T;
  std::vector<double> times;
  for (const auto& s : snapshots) {
    const FieldSnapshot f = read_field(run.dir / s.file);
    std::vector<particles::Vec<2>> x;
    std::vector<double> t;
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.boundary[i] < 0) x.push_back(f.position[i]), t.push_back(f.temperature[i]);
    if (points.empty()) points = x;
    if (x.size() != points.size()) continue;  // particles do not move: another cloud is not this run's
    T.push_back(std::move(t));
    times.push_back(s.time);
  }
  const double spacing = facts.value(keys::spacing, 0.0);
  const MapWindow window = window_over(points, spacing, 400);
  const CloudRaster cloud(points, triangle_edge(facts), window);
  const ColourScale colours = temperature_scale(T, run.freezing_point());
  const std::string unit = facts.value("time_unit", "s");
  const auto& fronts = run.summary.value(keys::interface, json::array());
  json maps = json::array();
  for (std::size_t k = 0; k < T.size(); ++k) {
    std::vector<post::Polyline> curves;
    if (k < fronts.size() && fronts[k].contains("file") && fs::exists(run.dir / fronts[k]["file"].get<std::string>()))
      curves = read_polylines(run.dir / fronts[k]["file"].get<std::string>());
    const std::string title = fmt::format("t = {:g} {}", times[k], unit);
    maps.push_back(
        {{"html", map_html(cloud.raster(T[k], colours), window, "temperature", curves, MapOverlay{}, title)},
         {"caption", fmt::format("Temperature at {:g} {}{}.", times[k], unit,
                                 curves.empty() ? "" : "; black line: frozen front (liquid fraction 0.5)")}});
  }
  view["maps"] = maps;
  view["has_maps"] = !maps.empty();
  view["show_maps_note"] = true;
  view["colour_bar_svg"] = colours.colour_bar_svg(520);
  const double Tf = run.freezing_point();
  view["maps_note"] = fmt::format(
      "The temperature of each snapshot on the particles' triangles, linear within each (as ParaView draws the VTK "
      "cells), on one colour scale{}.",
      Tf > colours.lo() && Tf < colours.hi()
          ? fmt::format(" turning from blue to red at the freezing point ({} °C)", number(Tf, 1))
          : std::string());
}

}  // namespace frostwall::report::detail
