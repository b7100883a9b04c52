// Where the project's sensors are read on the simulated cloud: a sensor
// anywhere in the section is mapped into the wedge by the section's
// symmetry (the field there is the same by construction).
#pragma once

#include <vector>

#include "freezing/model.hpp"
#include "particles/vec.hpp"

namespace frostwall::freezing {

// One point per project.monitoring entry, in its order.
std::vector<particles::Vec<2>> sensor_points(const project::Project& p, const Model& m);

}  // namespace frostwall::freezing
