// A soil given by its constituents (soil.porosity with soil.solid, .water
// and .ice): the frozen and unfrozen phases of today's soil computed from
// them. Internal to lib/project; problems go to the Node.
#pragma once

#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// The soil object n has "porosity": its phases from the constituents.
Soil soil_from_constituents(const Node& n);

}  // namespace frostwall::project::detail
