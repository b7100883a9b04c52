// The mechanics section of a PD thermo-mechanical run: at each snapshot
// the temperature, the displacement magnitude and the damage side by side
// (the PD paper's Figs. 7 and 10), each drawn on the particles' triangles
// (linear within each, as ParaView shows the VTK cells). The damage maps
// are left out when no bond can break or none broke; a porous plate's
// temperature and damage are in its frost section, so here it shows the
// displacement only.
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

namespace {

struct SolidSeries {
  std::vector<double> time;
  std::vector<SolidSnapshot> snapshot;
  double largest_u = 0.0, largest_damage = 0.0;
};

// The snapshots of field.pvd with the solid's fields, on the first one's particles.
SolidSeries read_solids(const RunRecord& run) {
  SolidSeries s;
  for (const auto& e : read_pvd(run.dir / "field.pvd")) {
    SolidSnapshot solid = read_solid(run.dir / e.file);
    const std::size_t n = solid.particles.position.size();
    if (n == 0 || (!s.snapshot.empty() && n != s.snapshot.front().particles.position.size())) continue;
    for (double u : solid.particles.temperature) s.largest_u = std::max(s.largest_u, u);
    for (double d : solid.damage) s.largest_damage = std::max(s.largest_damage, d);
    s.time.push_back(e.time);
    s.snapshot.push_back(std::move(solid));
  }
  return s;
}

}  // namespace

void add_mechanics(const RunRecord& run, json& view) {
  view["has_mechanics"] = false;
  view["has_damage_maps"] = false;
  view["mechanics_snapshots"] = json::array();
  for (const char* key : {"mechanics_note", "mechanics_maps_note", "displacement_bar_svg", "damage_bar_svg"})
    view[key] = "";
  view["mechanics_temperature_bar_svg"] = false;  // a section: false when there is none
  view["mechanics_grid"] = "maps";
  view["mechanics_heading"] = "Displacement";
  if (!run.mechanics()) return;
  const auto& facts = run.summary[keys::run];
  view["has_mechanics"] = true;
  const auto& m = facts["mechanics"];
  const bool breakable = m.value("critical_stretch", json()).is_number();
  const std::string solver =
      m.value("equilibrium", "") == "direct"
          ? fmt::format("{} equilibria solved directly ({} factorizations, {} conjugate-gradient iterations)",
                        m.value("direct_solves", 0), m.value("factorizations", 0), m.value("relaxation_iterations", 0))
          : fmt::format("{} relaxations ({} iterations of adaptive dynamic relaxation, {} unconverged)",
                        m.value("relaxations", 0), m.value("relaxation_iterations", 0),
                        m.value("unconverged_relaxations", 0));
  view["mechanics_note"] =
      fmt::format("Bond-based peridynamics: {} bonds, horizon {} mm; {}; {} bonds broken; largest displacement {} µm.",
                  m.value("bonds", 0), number(1e3 * m.value("horizon", 0.0), 3), solver, m.value("broken_bonds", 0),
                  number(1e6 * m.value("largest_displacement", 0.0), 3));
  const SolidSeries solids = read_solids(run);
  if (solids.snapshot.empty()) {
    view["mechanics_maps_note"] = "No snapshots of the solid in this directory (output.vtk is off), so no maps.";
    return;
  }
  const bool with_temperature = !run.frost() &&
                                solids.snapshot.front().temperature.size() == solids.snapshot.front().damage.size();
  const bool with_damage = !run.frost() && breakable && solids.largest_damage > 0.0;
  const auto& points = solids.snapshot.front().particles.position;
  const MapWindow window = window_over(points, facts.value(keys::spacing, 0.0), 300);
  const CloudRaster cloud(points, triangle_edge(facts), window);
  std::vector<std::vector<double>> temperatures;
  if (with_temperature)
    for (const auto& s : solids.snapshot) temperatures.push_back(s.temperature);
  const ColourScale temperature = temperature_scale(temperatures, run.freezing_point());
  // Displacement in micrometres, 0 to a round top; damage 0 to 1.
  const NiceScale top = nice_scale(0.0, std::max(1e6 * solids.largest_u, 1e-9), 6);
  const ColourScale displacement(0.0, top.hi, 0.5 * top.hi), damage(0.0, 1.0, 0.5);
  const std::string unit = facts.value("time_unit", "s");
  json rows = json::array();
  for (std::size_t k = 0; k < solids.snapshot.size(); ++k) {
    const auto& s = solids.snapshot[k];
    const double t = solids.time[k];
    const std::string title = fmt::format("t = {:g} {}", t, unit);
    auto map = [&](const std::vector<double>& v, const ColourScale& c, const std::string& what,
                   const std::string& caption) {
      return json{{"html", map_html(cloud.raster(v, c), window, what, {}, MapOverlay{}, title)},
                  {"caption", fmt::format("{} at {:g} {}", caption, t, unit)}};
    };
    std::vector<double> micro(s.particles.temperature.size());
    for (std::size_t i = 0; i < micro.size(); ++i) micro[i] = 1e6 * s.particles.temperature[i];
    json maps = json::array();
    if (with_temperature) maps.push_back(map(s.temperature, temperature, "temperature", "temperature (°C)"));
    maps.push_back(map(micro, displacement, "displacement", "|displacement| (µm)"));
    if (with_damage) maps.push_back(map(s.damage, damage, "damage", "damage (share of broken bonds)"));
    rows.push_back({{"maps", maps}});
  }
  if (!with_temperature && !with_damage) {  // the displacement alone: the snapshots side by side
    json all = json::array();
    for (const auto& r : rows) all.push_back(r["maps"][0]);
    rows = json::array({{{"maps", all}}});
  }
  view["mechanics_snapshots"] = rows;
  view["has_damage_maps"] = with_damage;
  view["mechanics_heading"] =
      with_temperature ? (with_damage ? "Temperature, displacement and damage" : "Temperature and displacement")
                       : (with_damage ? "Displacement and damage" : "Displacement");
  view["mechanics_grid"] = with_temperature == with_damage ? "maps3" : "maps";
  if (with_temperature) view["mechanics_temperature_bar_svg"] = temperature.colour_bar_svg(340);
  view["displacement_bar_svg"] = displacement.colour_bar_svg(340, "|displacement| (µm)");
  if (with_damage) view["damage_bar_svg"] = damage.colour_bar_svg(340, "damage (share of broken bonds)");
  std::string note =
      "Each snapshot drawn on the particles' triangles, linear within each (as ParaView draws the VTK cells).";
  if (run.frost()) note += " The temperature and the damage of the plate are in the frost damage section.";
  else if (!breakable) note += " No damage maps: the bonds cannot break (the material has no fracture energy).";
  else if (!with_damage) note += " No damage maps: no bond broke within the run.";
  view["mechanics_maps_note"] = note;
}

}  // namespace frostwall::report::detail
