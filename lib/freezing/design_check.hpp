// The wall check of a shaft run: at each snapshot, the thickness
// every formula asks for (design/wall_strength.hpp) with the allowable
// strength at the mean temperature of the thinnest ray's frozen stretch,
// the governing formula's value, and utilisation = required / achieved
// (the thinnest wall); then the first day the check is met (utilisation
// at or below 1) and whether it stays met.
#pragma once

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/project.hpp"

namespace frostwall::freezing {

struct WallCheck {
  std::optional<double> allowable;                        // MPa, at the wall's mean temperature
  std::optional<double> required;                         // m, the governing formula's
  std::optional<double> utilisation;                      // required / achieved; null before the wall stands
  nlohmann::json required_by = nlohmann::json::object();  // every formula: m, or null where invalid
};

// mean_temperature: over the thinnest ray's frozen stretch (null: none).
WallCheck check_wall(const project::Design& design, double excavation_radius, double min_thickness,
                     std::optional<double> mean_temperature);

struct DesignMet {
  std::optional<double> day;  // the first snapshot day with utilisation <= 1
  bool stays = false;         // and every later one too
};
DesignMet design_met(const std::vector<double>& days, const std::vector<WallCheck>& checks);

}  // namespace frostwall::freezing
