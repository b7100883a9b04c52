// What the title block and the headline cards of a plain geometry say: the
// method that ran and the few numbers of its physics, all from
// summary.json (a thermal run's front and sensors; a PD solid's
// displacement, broken bonds and cracks; a porous plate's pores).
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>

#include "project/json_numbers.hpp"
#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using project::number_or_nan;

using nlohmann::json;

namespace {

// A time of the run in its own unit: "400 s", "0.0062 s".
std::string at(double t, const std::string& unit) { return std::isfinite(t) ? fmt::format("{:.3g} {}", t, unit) : "–"; }

std::string micrometres(double metres) { return std::isfinite(metres) ? fmt::format("{:.3g} µm", 1e6 * metres) : "–"; }

// A length in µm below a millimetre, else in mm.
std::string length(double metres) {
  if (!std::isfinite(metres)) return "–";
  return metres < 1e-3 ? micrometres(metres) : fmt::format("{:.3g} mm", 1e3 * metres);
}

// The front's estimated error at time t (summary "front_error"), or null.
json front_error(const json& summary, double t) {
  for (const auto& row : summary.value(keys::error_of(keys::front), json::array()))
    if (row.is_array() && row.size() == 2 && row[0].is_number() && row[0].get<double>() == t) return row[1];
  return json();
}

const json& run_facts(const RunRecord& run) {
  static const json none = json::object();
  const auto it = run.summary.find(keys::run);
  return it != run.summary.end() && it->is_object() ? *it : none;
}

// The last reading of each sensor: "monitoring" {name: [[t, T], ...]}.
void sensor_temperature_cards(const RunRecord& run, const std::string& unit, json& cards) {
  const auto& m = run.summary.value(keys::monitoring, json::object());
  int shown = 0;
  for (const auto& [name, series] : m.items()) {
    if (!series.is_array() || series.empty() || shown == 4) continue;
    const auto& last = series.back();
    const auto& errors = run.summary.value(keys::error_of(keys::monitoring), json::object()).value(name, json::array());
    const json error = !errors.empty() && errors.back().size() > 1 ? errors.back()[1] : json();
    cards.push_back(card("Sensor " + name + ", " + at(number_or_nan(last[0]), unit),
                         with_error(last[1], error, 2) + " °C", "temperature"));
    ++shown;
  }
}

// The last reading of each sensor of the solid: "monitoring_solid" {name: [[t, ux, uy, damage], ...]}.
void sensor_displacement_cards(const RunRecord& run, const std::string& unit, json& cards) {
  const auto& m = run.summary.value(keys::monitoring_solid, json::object());
  const auto& heat = run.summary.value(keys::monitoring, json::object());
  int shown = 0;
  for (const auto& [name, series] : m.items()) {
    if (!series.is_array() || series.empty() || shown == 3) continue;
    const auto& last = series.back();
    const double ux = number_or_nan(last[1]), uy = number_or_nan(last[2]);
    std::string note = fmt::format("|u| of ux {}, uy {} µm", number(1e6 * ux, 3), number(1e6 * uy, 3));
    if (heat.contains(name) && heat[name].is_array() && !heat[name].empty())
      note += "; " + number(heat[name].back()[1], 2) + " °C";
    cards.push_back(
        card("Sensor " + name + ", " + at(number_or_nan(last[0]), unit), micrometres(std::hypot(ux, uy)), note));
    ++shown;
  }
}

// Broken bonds, the first crack and, when measured, the crack length.
void bond_cards(const RunRecord& run, const std::string& unit, json& cards) {
  const auto& m = run_facts(run)["mechanics"];
  if (!m.value("critical_stretch", json()).is_number()) {
    cards.push_back(card("Broken bonds", "none", "the bonds cannot break: the material has no fracture energy"));
    return;
  }
  const double bonds = number_or_nan(m.value("bonds", json())), broken = number_or_nan(m.value("broken_bonds", json()));
  cards.push_back(card("Broken bonds", bonds > 0 ? fmt::format("{:.3g} %", 100.0 * broken / bonds) : "–",
                       fmt::format("{:.0f} of {:.0f} bonds, at the end of the run", broken, bonds)));
  const auto& first = m.value("first_damage", json());
  cards.push_back(first.is_object() ? card("First crack", at(number_or_nan(first.value("time", json())), unit),
                                           fmt::format("first broken bonds near x = {}, y = {}",
                                                       length(number_or_nan(first.value("x", json()))),
                                                       length(number_or_nan(first.value("y", json())))))
                                    : card("First crack", "none", "no bond broke within the run"));
  const auto& damage = run.summary.value(keys::damage, json::array());
  if (!damage.empty() && damage.back().contains("crack_length"))
    cards.push_back(card("Crack length, " + at(number_or_nan(damage.back().value("time", json())), unit),
                         length(number_or_nan(damage.back()["crack_length"])),
                         "both faces of the cracks (damage above 0.4)"));
  else if (m.contains("crack_length"))
    cards.push_back(card("Crack length", length(number_or_nan(m["crack_length"])),
                         "at the end of the run; both faces of the cracks (damage above 0.4)"));
}

void pore_cards(const RunRecord& run, const std::string& unit, json& cards) {
  const auto& pores = run.summary[keys::pores];
  const double all = number_or_nan(run.summary.value("all_pores_frozen", json()));
  std::size_t frozen = 0, cracked = 0, told = 0;
  double lo = 1.0, hi = 0.0;
  for (const auto& p : pores) {
    frozen += p.value("freezing_end", json()).is_number();
    if (p.contains("cracked")) ++told, cracked += p["cracked"].is_boolean() && p["cracked"].get<bool>();
    const double S = p.contains("saturation") ? number_or_nan(p["saturation"]) : 1.0;
    if (std::isfinite(S)) lo = std::min(lo, S), hi = std::max(hi, S);
  }
  cards.push_back(
      std::isfinite(all)
          ? card("All pores frozen by", at(all, unit), fmt::format("{} water-filled pores", pores.size()))
          : card("Pores frozen", fmt::format("{} of {}", frozen, pores.size()), "not all frozen within the run"));
  if (told > 0 && run.mechanics())  // no solid, nothing to crack
    cards.push_back(card("Pores cracked", fmt::format("{} of {}", cracked, pores.size()),
                         "a broken bond within a horizon outside the rim"));
  if (!pores.empty())
    cards.push_back(card("Saturation", lo == hi ? number(lo, 3) : number(lo, 3) + " – " + number(hi, 3),
                         "the share of a pore its water fills; below 0.917 the ice fits"));
}

}  // namespace

std::optional<std::pair<double, double>> last_front(const json& summary) {
  // The front is measured from the face's row of particles (frozen by
  // assumption) to the first row at least half liquid: with nothing frozen
  // beyond the face it sits half a spacing in.
  const double spacing = summary.value(keys::run, json::object()).value(keys::spacing, 0.0);
  std::optional<std::pair<double, double>> last;
  for (const auto& f : summary.value(keys::front, json::array()))
    if (f.is_array() && f.size() == 2 && f[0].is_number() && f[1].is_number() &&
        f[1].get<double>() > 0.5 * spacing * (1.0 + 1e-6))
      last = std::pair{f[0].get<double>(), f[1].get<double>()};
  return last;
}

json card(const std::string& label, const std::string& value, const std::string& note) {
  return {{"label", label}, {"value", value}, {"note", note}};
}

std::string method_line(const RunRecord& run) {
  if (run.summary.value(keys::physics, std::string()) == "cfd-dem")
    return "Grains and pore water: DEM grains in LAMMPS coupled with a coarse-grid flow (CFD-DEM).";
  const bool pd = run_facts(run).value("method", std::string()) == "pd";
  const std::string heat = pd ? "peridynamic (PD) heat conduction" : "SPH heat conduction";
  if (run.frost())
    return "Frost damage of a porous solid: " + heat + ", freezing pore water" +
           (run.mechanics() ? " and bond-based peridynamic (PD) mechanics." : ".");
  if (run.mechanics()) return "Thermo-mechanics: " + heat + " and bond-based peridynamic (PD) mechanics.";
  if (run.shaft()) return "Artificial ground freezing: " + heat + " with latent heat.";
  return "Heat conduction on a plain geometry: " + heat + (pd ? "." : " with latent heat.");
}

void add_plain_headline(const RunRecord& run, json& view) {
  const std::string unit = run_facts(run).value("time_unit", "s");
  json cards = json::array();
  if (run.frost()) pore_cards(run, unit, cards);
  if (run.mechanics()) {
    const auto& m = run_facts(run)["mechanics"];
    cards.push_back(card("Largest displacement", micrometres(number_or_nan(m.value("largest_displacement", json()))),
                         "anywhere in the solid, at the end of the run"));
    if (!run.frost()) sensor_displacement_cards(run, unit, cards);
    bond_cards(run, unit, cards);
  }
  if (!run.mechanics() && !run.frost()) {
    // The front only where one formed: a plate that never freezes has none.
    if (const auto front = last_front(run.summary))
      cards.push_back(card("Frozen front, " + at(front->first, unit),
                           with_error(front->second, front_error(run.summary, front->first), 4) + " m",
                           "from the cooled face (liquid fraction 0.5)"));
    sensor_temperature_cards(run, unit, cards);
  }
  view["cards"] = cards;
  view["has_cards"] = !cards.empty();
}

}  // namespace frostwall::report::detail
