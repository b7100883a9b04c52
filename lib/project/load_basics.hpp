// Readers every geometry uses: temperature schedules and the soil.
// Internal to lib/project; problems go to the Node.
#pragma once

#include <string>
#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// A number, or [[day, degC], ...] with days ascending.
TemperatureSchedule read_schedule(const Node& n, const char* unit = "degC");
// A built-in soil's name or a soil object; an implausible latent heat warns.
Soil read_soil(const Node& n, std::vector<std::string>& warnings);
// A rectangle's spacing must leave at least 2 particle rows across its
// narrow side (a strip two rows high between mirror sides is a 1-D
// problem) and 5 along its long side; else one problem on numerics.spacing.
void check_rectangle_spacing(const Node& spacing_node, const Rectangle& r, std::optional<double> spacing);
// A shaft section's finest spacing must not exceed the pipe diameter.
void check_shaft_spacing(const Node& spacing_node, const ShaftSection& s, std::optional<double> spacing);

}  // namespace frostwall::project::detail
