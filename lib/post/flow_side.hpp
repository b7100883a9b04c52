// Which side of the shaft a direction from its axis faces under a regional
// groundwater flow q: upstream within 60 degrees of against the flow,
// downstream within 60 degrees of along it, a flank between. One rule for
// the gaps' positions and the wall's upstream/downstream thickness.
#pragma once

#include <array>
#include <cmath>

#include "particles/vec.hpp"

namespace frostwall::post {

enum class FlowSide { upstream, flank, downstream };

inline FlowSide flow_side(const particles::Vec<2>& direction, const std::array<double, 2>& q) {
  const double along = (direction[0] * q[0] + direction[1] * q[1]) /
                       (direction.norm() * std::hypot(q[0], q[1]) + 1e-300);
  return along < -0.5 ? FlowSide::upstream : (along > 0.5 ? FlowSide::downstream : FlowSide::flank);
}

inline const char* name(FlowSide side) {
  return side == FlowSide::upstream ? "upstream" : (side == FlowSide::downstream ? "downstream" : "flank");
}

}  // namespace frostwall::post
