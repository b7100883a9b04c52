// The built-in soils: the soils of Chen & Bai (2016), see shared/spec/physics.md.
#include <utility>

#include "project/project.hpp"

namespace frostwall::project {
namespace {

PhaseProperties isotropic(double conductivity, double heat_capacity) {
  return {{conductivity, conductivity}, heat_capacity};
}

const std::pair<const char*, Soil> builtin_soils[] = {
    // Section 3, single ring.
    {"sand",
     {.name = "medium-coarse sand",
      .density = 2090,
      .unfrozen = isotropic(1.86, 1465.1),
      .frozen = isotropic(2.56, 1088.4),
      .latent_heat = 52875.8,
      .freezing_point = 0.0,
      .freezing_curve = {}}},
    // Section 3; the paper prints L = 530718, a slipped decimal point (more
    // than pure water's 334 kJ/kg).
    {"clay",
     {.name = "clay",
      .density = 2050,
      .unfrozen = isotropic(1.51, 1548.8),
      .frozen = isotropic(2.05, 1172.1),
      .latent_heat = 53071.8,
      .freezing_point = 0.0,
      .freezing_curve = {}}},
    // Section 2.2, the soil column.
    {"silty_clay",
     {.name = "silty clay",
      .density = 1800,
      .unfrozen = isotropic(3.05, 2124.0),
      .frozen = isotropic(2.68, 2508.5),
      .latent_heat = 33500.0,
      .freezing_point = -0.25,
      .freezing_curve = {}}},
};

}  // namespace

std::optional<Soil> builtin_soil(const std::string& name) {
  for (const auto& [key, soil] : builtin_soils)
    if (name == key) return soil;
  return std::nullopt;
}

std::vector<std::string> builtin_soil_names() {
  std::vector<std::string> names;
  for (const auto& entry : builtin_soils) names.emplace_back(entry.first);
  return names;
}

}  // namespace frostwall::project
