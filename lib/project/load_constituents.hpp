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

// soil.freezing_curve (and the older soil.freezing_range) into soil;
// water_content: kg of water per kg of solid when unfrozen, known for a
// soil from its constituents (0: the power curve must give it).
void read_freezing_curve(const Node& soil_node, Soil& soil, double water_content);

}  // namespace frostwall::project::detail
