// Readers every geometry uses: temperature schedules and the soil.
// Internal to lib/project; problems go to the Node.
#pragma once

#include <string>
#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// A number, or [[day, degC], ...] with days ascending.
TemperatureSchedule read_schedule(const Node& n);
// A built-in soil's name or a soil object; an implausible latent heat warns.
Soil read_soil(const Node& n, std::vector<std::string>& warnings);

}  // namespace frostwall::project::detail
