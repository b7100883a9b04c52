// The mechanics section of a PD thermo-mechanical run: maps of the
// displacement magnitude and of the damage at each snapshot (the solid's
// particles resampled like the temperature maps), and the sensors'
// displacements and damage over time (monitoring.csv).
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>
#include <regex>

#include "report/field_map.hpp"
#include "report/nice_scale.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"

namespace frostwall::report::detail {

using nlohmann::json;
namespace fs = std::filesystem;

void add_mechanics(const RunRecord& run, json& view) {
  view["has_mechanics"] = false;
  for (const char* key : {"displacement_maps", "damage_maps"}) view[key] = json::array();
  for (const char* key : {"mechanics_note", "displacement_bar_svg", "damage_bar_svg"}) view[key] = "";
  const auto& facts = run.summary.value("run", json::object());
  if (!facts.contains("mechanics")) return;
  view["has_mechanics"] = true;
  const auto& m = facts["mechanics"];
  view["mechanics_note"] = fmt::format(
      "Bond-based peridynamics: {} bonds, horizon {} mm; {} relaxations ({} iterations of adaptive dynamic relaxation, "
      "{} unconverged); {} bonds broken; largest displacement {} µm.",
      m.value("bonds", 0), number(1e3 * m.value("horizon", 0.0), 3), m.value("relaxations", 0),
      m.value("relaxation_iterations", 0), m.value("unconverged_relaxations", 0), m.value("broken_bonds", 0),
      number(1e6 * m.value("largest_displacement", 0.0), 3));
  // The snapshots of field.pvd, in order.
  const auto text = read_text(run.dir / "field.pvd");
  if (!text) return;
  static const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)")re");
  std::vector<std::pair<double, SolidSnapshot>> snapshots;
  double largest = 0.0;
  for (auto it = std::sregex_iterator(text->begin(), text->end(), dataset); it != std::sregex_iterator(); ++it) {
    snapshots.emplace_back(std::stod((*it)[1].str()), read_solid(run.dir / (*it)[2].str()));
    for (double u : snapshots.back().second.particles.temperature) largest = std::max(largest, u);
  }
  if (snapshots.empty() || snapshots.front().second.damage.empty() || !run.project) return;
  const auto* rect = std::get_if<project::Rectangle>(&run.project->geometry);
  if (!rect) return;
  const double spacing = facts.value("spacing", 0.0), h = smoothing_length(facts);
  const std::string unit = facts.value("time_unit", "s");
  MapWindow window;
  window.pixels = 300;
  window.size = std::max(rect->width, rect->height);
  const FieldMap map(snapshots.front().second.particles, WedgeSymmetry{}, facts.value("kernel", "wendland_c2"), h, spacing,
                     window, 0.0);
  // Displacement in micrometres, 0 to a round top; damage 0 to 1.
  const NiceScale top = nice_scale(0.0, std::max(1e6 * largest, 1e-9), 6);
  const ColourScale displacement(0.0, top.hi, 0.5 * top.hi), damage(0.0, 1.0, 0.5);
  json u_maps = json::array(), d_maps = json::array();
  for (const auto& [t, s] : snapshots) {
    std::vector<double> micro(s.particles.temperature.size());
    for (std::size_t i = 0; i < micro.size(); ++i) micro[i] = 1e6 * s.particles.temperature[i];
    const std::string title = fmt::format("t = {:g} {}", t, unit);
    u_maps.push_back({{"html", map.html(micro, displacement, {}, true, MapOverlay{}, title)},
                      {"caption", fmt::format("|displacement| (µm) at {:g} {}", t, unit)}});
    d_maps.push_back({{"html", map.html(s.damage, damage, {}, true, MapOverlay{}, title)},
                      {"caption", fmt::format("damage (share of broken bonds) at {:g} {}", t, unit)}});
  }
  view["displacement_maps"] = u_maps;
  view["damage_maps"] = d_maps;
  view["displacement_bar_svg"] = displacement.colour_bar_svg(520, "|displacement| (µm)");
  view["damage_bar_svg"] = damage.colour_bar_svg(520, "damage (share of broken bonds)");
}

}  // namespace frostwall::report::detail
