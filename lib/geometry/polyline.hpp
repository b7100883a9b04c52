// An open or closed curve in the plane: isolines, crack lines, fronts.
#pragma once

#include <vector>

#include "particles/vec.hpp"

namespace frostwall::geometry {

// A closed polyline does not repeat its first point at the end.
struct Polyline {
  std::vector<particles::Vec<2>> points;
  bool closed = false;
};

}  // namespace frostwall::geometry
