// A fixed-temperature boundary: the particles that carry its id hold the
// schedule's temperature (pipe walls, far field, cooled faces). Adiabatic
// sides are not here: they are mirror planes of the particle set.
//
// A wall behind a film (brine in a freeze pipe) is a Robin condition: the
// schedule is then the fluid's temperature, and the wall's own temperature
// follows from the heat the ground gives up to it, Q = h P (T_wall - T_fluid)
// per metre, P the wall's perimeter. The wall has no heat capacity, so the
// balance holds at every instant; one temperature per group (per pipe: the
// steel is thin and conducts well, so its wall is taken as one temperature
// around the pipe, as a fixed-temperature pipe is).
//
// A wall held at the heat it draws (drawn_heat) uses the same groups: the
// schedule is then the heat drawn per metre of the whole pipe, W/m, and
// each group's temperature is the one at which the ground gives up its
// share of it (perimeter / full_perimeter).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "project/project.hpp"

namespace frostwall::geometry {

struct FilmWall {
  double heat_transfer_coefficient = 0.0;  // h, W/(m2 K)
  std::vector<int> group;                  // per fixed particle (index i - free count); -1: not on this wall
  std::vector<double> perimeter;           // per group: m of its wall inside the simulated section
  bool drawn_heat = false;                 // the schedule is the heat drawn, W/m; no film
  double full_perimeter = 0.0;             // m: one whole pipe's wall (drawn_heat)
};

struct FixedTemperatureBoundary {
  std::string name;  // "pipe", "far_field", "left", ...
  project::TemperatureSchedule temperature;
  std::optional<FilmWall> film = std::nullopt;  // set: the schedule is the fluid's, behind a film
  // No heat conducted through the face: its particles copy the field at
  // their reflections (an adiabatic face that water flows through; the
  // schedule is 0, see sph/wall_extrapolation.hpp).
  bool insulated = false;
};

}  // namespace frostwall::geometry
