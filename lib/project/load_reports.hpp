// Readers of the project file's reporting blocks: design targets, sensors
// (and whether they lie in the simulated domain), output. Internal to
// lib/project (load_project.cpp calls them); problems go to the Node.
#pragma once

#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

Design read_design(const Node& n);
std::vector<Sensor> read_monitoring(const Node& n);
// A sensor must lie in the simulated ground: inside the far-field circle
// of a shaft section, inside a plain geometry's rectangle [0, w] x [0, h].
void check_sensors_inside(const Project& project, const Node& n);
Output read_output(const Node& n);

}  // namespace frostwall::project::detail
