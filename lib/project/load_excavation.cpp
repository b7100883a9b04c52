#include "project/load_excavation.hpp"

#include <fmt/format.h>

#include "project/load_basics.hpp"
#include "project/units.hpp"

namespace frostwall::project::detail {

namespace {

// A total in J/kg released over a time, or a [day, J/kg] table.
HydrationHeat read_hydration(const Node& n) {
  HydrationHeat q;
  if (!n.present()) return q;
  if (n.json().is_array()) {
    const auto size = n.array().value_or(0);
    if (size == 0) n.problem("must hold at least one [day, J/kg] point");
    auto& points = q.released.points;
    points.emplace_back(0.0, 0.0);  // nothing released at placing
    for (std::size_t k = 0; k < size; ++k) {
      const Node point = n[k];
      if (point.array().value_or(0) != 2) {
        point.problem("must be [day, J/kg]");
        continue;
      }
      const auto day = point[0].positive(), heat = point[1].non_negative();
      if (!day || !heat) continue;
      if (*day * seconds_per_day <= points.back().first) point[0].problem("days must ascend");
      else if (*heat < points.back().second) point[1].problem("the heat released so far must not fall");
      else points.emplace_back(*day * seconds_per_day, *heat);
    }
    return q;
  }
  if (!n.object({"total", "release_days"})) return q;
  q.total = n["total"].required().non_negative().value_or(0.0);
  q.release_time = n["release_days"].required().positive().value_or(1.0) * seconds_per_day;
  return q;
}

Lining read_lining(const Node& n, double radius) {
  Lining l;
  if (!n.object({"thickness", "conductivity", "heat_capacity", "density", "hydration_heat", "placed_after_days",
                 "placement_temperature"}))
    return l;
  l.thickness = n["thickness"].required().positive().value_or(0.0);
  if (radius > 0.0 && l.thickness >= radius)
    n["thickness"].problem(
        fmt::format("must be below the excavation radius {} (shaft.excavation_radius), got {}", radius, l.thickness));
  l.conductivity = n["conductivity"].required().positive().value_or(1.0);
  l.heat_capacity = n["heat_capacity"].required().positive().value_or(1.0);
  l.density = n["density"].required().positive().value_or(1.0);
  l.hydration = read_hydration(n["hydration_heat"]);
  l.placed_after =
      n["placed_after_days"].present() ? n["placed_after_days"].non_negative().value_or(0.0) * seconds_per_day : 0.0;
  if (n["placement_temperature"].present()) l.placement_temperature = n["placement_temperature"].number();
  return l;
}

// How many sections the project runs, for `days`: its layers, its
// survey's listed depths, or one (nullopt: a survey checked every few
// metres, whose sections are not known before it is read).
std::optional<std::size_t> section_count(const Project& p) {
  if (p.survey) return p.sections.depths.empty() ? std::nullopt : std::optional(p.sections.depths.size());
  return p.layers.empty() ? 1 : p.layers.size();
}

void read_sinking(const Node& n, const Project& p, Excavation& e) {
  const Node rate = n["rate_m_per_day"], days = n["days"];
  if (rate.present() == days.present()) {
    rate.problem(R"(give either "rate_m_per_day" (with "start_day") or "days" (one per section))");
    return;
  }
  if (rate.present()) {
    e.rate = rate.positive();
    e.start_day = n["start_day"].required().non_negative().value_or(0.0);
    return;
  }
  if (n["start_day"].present()) n["start_day"].problem(R"(only used with "rate_m_per_day")");
  const auto size = days.array();
  if (!size) return;
  const auto sections = section_count(p);
  if (!sections) days.problem(R"(needs the survey's sections listed ("sections": {"depths": [...]}), one day each)");
  else if (*size != *sections)
    days.problem(fmt::format("must give one day per section ({}), got {}", *sections, *size));
  for (std::size_t k = 0; k < *size; ++k) e.days.push_back(days[k].non_negative().value_or(0.0));
}

}  // namespace

std::optional<Excavation> read_excavation(const Node& root, const Project& project) {
  const Node n = root["excavation"];
  if (!n.present()) return std::nullopt;
  const auto* section = std::get_if<ShaftSection>(&project.geometry);
  if (!section) {
    n.problem(R"(only used with "layout" (shaft sections))");
    return std::nullopt;
  }
  if (!n.object({"start_day", "rate_m_per_day", "days", "depth", "air_temperature", "heat_transfer", "lining"}))
    return std::nullopt;
  Excavation e;
  read_sinking(n, project, e);
  const double radius = section->shaft.excavation_radius.value_or(0.0);
  if (!section->shaft.excavation_radius) n.problem(R"(needs "shaft": {"excavation_radius"} (the ground taken out))");
  if (const Node depth = n["depth"]; depth.present()) {
    if (!project.layers.empty() || project.survey)
      depth.problem(R"(each layer or section sinks at its own depth: not used with "layers" or "survey")");
    e.depth = depth.non_negative().value_or(0.0);
  } else if (project.design.depth) {
    e.depth = *project.design.depth;
  }
  e.air_temperature = read_schedule(n["air_temperature"].required());
  e.heat_transfer = n["heat_transfer"].required().non_negative().value_or(0.0);
  if (n["lining"].present()) e.lining = read_lining(n["lining"], radius);
  if (project.groundwater && project.groundwater->speed() > 0.0)
    n.problem(R"(not used with flowing groundwater ("groundwater" with a flux) in this version)");
  if (project.numerics.method == Method::pd) n.problem(R"(needs "numerics": {"method": "sph"})");
  if (project.compare_intact) root["compare_intact"].problem(R"(not used with "excavation")");
  return e;
}

}  // namespace frostwall::project::detail
