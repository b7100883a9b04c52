// A fixed-temperature boundary: the particles that carry its id hold the
// schedule's temperature (pipe walls, far field, cooled faces). Adiabatic
// sides are not here: they are mirror planes of the particle set.
#pragma once

#include <string>

#include "project/project.hpp"

namespace frostwall::thermal {

struct FixedTemperatureBoundary {
  std::string name;  // "pipe", "far_field", "left", ...
  project::TemperatureSchedule temperature;
};

}  // namespace frostwall::thermal
