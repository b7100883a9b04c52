// Inputs the twin and plant tests share: sand with its conductivities and
// latent heat scaled (a calibration twin's ground), and the coaxial pipe's
// fields of the shipped shaft with its plant.
#pragma once

#include <nlohmann/json.hpp>

#include "project/project.hpp"

namespace frostwall::test {

// The shipped sand with its frozen and unfrozen conductivities and its
// latent heat times the factors, as a project's "soil".
inline nlohmann::json scaled_sand(double frozen, double unfrozen, double latent) {
  const auto sand = *project::builtin_soil("sand");
  return {
      {"name", "twin"},
      {"density", sand.density},
      {"unfrozen",
       {{"conductivity", sand.unfrozen.conductivity[0] * unfrozen}, {"heat_capacity", sand.unfrozen.heat_capacity}}},
      {"frozen",
       {{"conductivity", sand.frozen.conductivity[0] * frozen}, {"heat_capacity", sand.frozen.heat_capacity}}},
      {"latent_heat", sand.latent_heat * latent},
      {"freezing_point", sand.freezing_point}};
}

// A 127 mm steel freeze pipe with a 63 mm polyethylene inner pipe, `length` m.
inline nlohmann::json coaxial_pipe(double length) {
  return {{"diameter", 0.127},
          {"wall_thickness", 0.006},
          {"inner_diameter", 0.063},
          {"inner_wall_thickness", 0.0058},
          {"length", length}};
}

}  // namespace frostwall::test
