// Temperature schedules and soils (load_basics.hpp).
#include "project/load_basics.hpp"
#include "project/load_constituents.hpp"

#include <algorithm>
#include <array>
#include <fmt/format.h>

#include "project/units.hpp"

namespace frostwall::project {

using detail::Json;
using detail::Node;

namespace {

constexpr double pure_water_latent_heat = 334000.0;  // J/kg

std::array<double, 2> read_conductivity(const Node& n) {
  if (!n.given()) return {};
  if (n.json().is_array()) {
    if (n.json().size() != 2) {
      n.problem(fmt::format("must be a number or [kx, ky], got an array of {}", n.json().size()));
      return {};
    }
    return {n[0].required().positive().value_or(0.0), n[1].required().positive().value_or(0.0)};
  }
  if (!n.json().is_number()) {
    n.problem("must be a number or [kx, ky], got " + n.type());
    return {};
  }
  const double k = n.positive().value_or(0.0);
  return {k, k};
}

}  // namespace

// A wall temperature: a number, or [[day, degC], ...] with days ascending
// (another quantity in time: its unit in the messages).
TemperatureSchedule detail::read_schedule(const Node& n, const char* unit) {
  TemperatureSchedule schedule = TemperatureSchedule::fixed(0.0);
  if (!n.given()) return schedule;
  if (n.json().is_number()) return TemperatureSchedule::fixed(n.json().get<double>());
  if (!n.json().is_array()) {
    n.problem(fmt::format("must be a number or a [[day, {}], ...] schedule, got {}", unit, n.type()));
    return schedule;
  }
  if (n.json().empty()) {
    n.problem(fmt::format("must have at least one [day, {}] point", unit));
    return schedule;
  }
  schedule.points.clear();
  for (std::size_t i = 0; i < n.json().size(); ++i) {
    const Node point = n[i];
    const Json& p = point.json();
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      point.problem(fmt::format("must be a [day, {}] pair, got {}", unit, p.is_array() ? point.shown() : point.type()));
      continue;
    }
    const double day = p[0].get<double>();
    const double seconds = day * seconds_per_day;
    if (!schedule.points.empty() && seconds <= schedule.points.back().first)
      point.problem(
          fmt::format("days must be ascending, got {} after {}", day, schedule.points.back().first / seconds_per_day));
    else schedule.points.emplace_back(seconds, p[1].get<double>());
  }
  if (schedule.points.empty()) schedule = TemperatureSchedule::fixed(0.0);
  return schedule;
}

Soil detail::read_soil(const Node& n, std::vector<std::string>& warnings) {
  Soil soil;
  if (!n.given()) return soil;
  if (n.json().is_string()) {
    const auto name = n.json().get<std::string>();
    if (auto builtin = builtin_soil(name)) return *builtin;
    std::string names;
    for (const auto& known : builtin_soil_names()) names += (names.empty() ? "" : ", ") + known;
    n.problem("unknown soil '" + name + "' (built-in: " + names + ")");
    return soil;
  }
  if (!n.json().is_object()) {
    n.problem("must be a built-in soil name or an object, got " + n.type());
    return soil;
  }
  if (n["porosity"].present()) {
    for (const char* key : {"density", "unfrozen", "frozen", "latent_heat"})
      if (n[key].present()) n[key].problem(R"(computed from the constituents with "porosity"; give one or the other)");
    return soil_from_constituents(n);
  }
  n.object(
      {"name", "density", "unfrozen", "frozen", "latent_heat", "freezing_point", "freezing_range", "freezing_curve"});
  soil.name = n["name"].string().value_or("custom soil");
  soil.density = n["density"].required().positive().value_or(0.0);
  for (const auto& [key, phase] : {std::pair{"unfrozen", &soil.unfrozen}, std::pair{"frozen", &soil.frozen}}) {
    const Node p = n[key].required();
    if (!p.object({"conductivity", "heat_capacity"})) continue;
    phase->conductivity = read_conductivity(p["conductivity"].required());
    phase->heat_capacity = p["heat_capacity"].required().positive().value_or(0.0);
  }
  // Zero is allowed: a soil without phase change (pure conduction checks).
  soil.latent_heat = n["latent_heat"].required().non_negative().value_or(0.0);
  soil.freezing_point = n["freezing_point"].number().value_or(0.0);
  read_freezing_curve(n, soil, 0.0);
  if (soil.latent_heat > pure_water_latent_heat)
    warnings.push_back(
        fmt::format("{}: {} J/kg is more than pure water's 334 kJ/kg; probably a slipped decimal point ({}?)",
                    n["latent_heat"].path(), soil.latent_heat, soil.latent_heat / 10));
  return soil;
}

std::optional<std::string> rectangle_spacing_problem(const Rectangle& r, double spacing) {
  if (!(r.width > 0) || !(r.height > 0)) return std::nullopt;
  constexpr double rows_across_narrow = 2.0, rows_along_long = 5.0;
  const bool wide = r.width >= r.height;
  const double narrow = std::min(r.width, r.height), longer = std::max(r.width, r.height);
  const bool long_binds = longer / rows_along_long <= narrow / rows_across_narrow;
  const double rows = long_binds ? rows_along_long : rows_across_narrow, side = long_binds ? longer : narrow;
  const char* key = (long_binds == wide) ? "geometry.width" : "geometry.height";
  if (spacing <= side / rows * (1 + 1e-9)) return std::nullopt;
  return fmt::format("{} m leaves fewer than {} particle rows across {} ({} m); use {} m or less", spacing, rows, key,
                     side, side / rows);
}

std::optional<std::string> shaft_spacing_problem(const ShaftSection& s, double spacing) {
  // A line sink needs no particles across its pipe (the gap between two
  // pipes bounds its spacing: freezing/capacity.cpp).
  if (s.pipe.model == PipeModel::line) return std::nullopt;
  if (!(s.pipe.diameter > 0) || spacing <= s.pipe.diameter * (1 + 1e-9)) return std::nullopt;
  return fmt::format("{} m is larger than the pipe diameter ({} m): a pipe needs particles across it; use {} m or less",
                     spacing, s.pipe.diameter, s.pipe.diameter);
}

void check_spacing(const Project& p) {
  if (!p.numerics.spacing) return;
  std::optional<std::string> problem;
  if (const auto* r = std::get_if<Rectangle>(&p.geometry)) problem = rectangle_spacing_problem(*r, *p.numerics.spacing);
  if (const auto* s = std::get_if<ShaftSection>(&p.geometry)) problem = shaft_spacing_problem(*s, *p.numerics.spacing);
  if (problem) throw ProjectError({"numerics.spacing: " + *problem});
}

void detail::check_rectangle_spacing(const Node& spacing_node, const Rectangle& r, std::optional<double> spacing) {
  if (!spacing) return;
  if (const auto problem = rectangle_spacing_problem(r, *spacing)) spacing_node.problem(*problem);
}

void detail::check_shaft_spacing(const Node& spacing_node, const ShaftSection& s, std::optional<double> spacing) {
  if (!spacing) return;
  if (const auto problem = shaft_spacing_problem(s, *spacing)) spacing_node.problem(*problem);
}

}  // namespace frostwall::project
