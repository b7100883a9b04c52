// The groundwater's flow on the temperature maps: arrows of the
// Darcy flux on a square grid over the map window, each the flux of the
// nearest free particle to its grid point. The point is folded into the
// simulated section first, and the flux mirrored with it (seepage keeps at
// most the one mirror line along the flow). Arrows are scaled so the
// longest is 0.9 of the grid's step: their lengths compare speeds on one
// map.
#pragma once

#include <vector>

#include "report/field_map.hpp"
#include "report/run_files.hpp"
#include "report/wedge_symmetry.hpp"

namespace frostwall::report {

// Empty when the snapshot carries no flux or the symmetry has more than one
// mirror line. `domain_radius` > 0 leaves out points beyond it.
std::vector<Arrow> flow_arrows(const FieldSnapshot& field, const WedgeSymmetry& symmetry, const MapWindow& window,
                               double domain_radius, int per_side = 18);

}  // namespace frostwall::report
