// A soil read through a minimal project (the loader's soil, as a run sees
// it), and InterFrost TH2's sand by its constituents (the soil object left
// open for further fields).
#pragma once

#include <string>

#include "project/project.hpp"

namespace frostwall::testing {

inline project::Soil soil_of(const std::string& soil) {
  return project::parse_project(R"({ "name": "c", "geometry": { "type": "rectangle", "width": 1, "height": 1,
      "boundaries": { "left": "adiabatic", "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" } },
    "soil": )" + soil + R"(, "domain": { "initial_temperature": 5 }, "time": { "end": 1, "unit": "s" },
    "numerics": { "spacing": 0.05 }, "output": { "directory": "unused" } })")
      .soil;
}

inline const std::string th2_constituents = R"({ "porosity": 0.37,
    "solid": { "density": 2650, "heat_capacity": 835, "conductivity": 9 },
    "water": { "density": 1000, "heat_capacity": 4182, "conductivity": 0.6, "latent_heat": 3.34e5 },
    "ice":   { "density": 920,  "heat_capacity": 2060, "conductivity": 2.14 })";

}  // namespace frostwall::testing
