// Readers of the project file's reporting blocks: design targets, sensors
// (and whether they lie in the simulated domain), output. Internal to
// lib/project (load_project.cpp calls them); problems go to the Node.
#pragma once

#include <optional>
#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// layered: the project has layers, whose depths stand in for the design's.
Design read_design(const Node& n, bool layered = false);
// Frozen-soil strength: [[T, sigma_c], ...], {"a", "b"} or {"sigma_0", "k", "m"}.
std::optional<StrengthLaw> read_strength(const Node& n);
// Lateral pressure (MPa): a value, a gradient times the depth, or gamma z K;
// depth_node names the depth a gradient needs when it is missing.
std::optional<double> read_pressure(const Node& n, std::optional<double> depth, const Node& depth_node);
std::vector<Sensor> read_monitoring(const Node& n);
// A sensor must lie in the simulated ground: inside the far-field circle
// of a shaft section, inside a plain geometry's rectangle [0, w] x [0, h].
void check_sensors_inside(const Project& project, const Node& n);
Output read_output(const Node& n);

}  // namespace frostwall::project::detail
