// domain.initial_zones: parts of the domain that start at their own
// temperature. Internal to lib/project; problems go to the Node.
#pragma once

#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

std::vector<InitialZone> read_initial_zones(const Node& n);

}  // namespace frostwall::project::detail
