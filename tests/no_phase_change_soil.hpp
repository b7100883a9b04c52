// A soil that never freezes (the freezing point far below anything the
// tests reach): conduction and the water's heat checked on their own.
#pragma once

#include <string>

#include "project/project.hpp"

namespace frostwall::test {

inline project::Soil no_phase_change_soil(const std::string& name, double conductivity, double heat_capacity) {
  project::Soil soil;
  soil.name = name;
  soil.density = 2000.0;
  soil.unfrozen = {{conductivity, conductivity}, heat_capacity / soil.density};
  soil.frozen = soil.unfrozen;
  soil.freezing_point = -100.0;
  return soil;
}

}  // namespace frostwall::test
