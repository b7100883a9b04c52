// The section's two reference rays, where walls and interfaces are read.
#pragma once

#include <vector>

#include "geometry/layout.hpp"

namespace frostwall::geometry {

// OA, the ray through the first pipe of the outer ring, and OB, halfway to
// the next pipe of that ring counter-clockwise; the ring radius of OA's pipe
// and the radii of every ring (mean radius of its pipes; measured pipes,
// which form no ring, count as OA's).
struct InterfacePlanes {
  double OA = 0.0, OB = 0.0;       // rad
  double ring_radius = 0.0;        // m
  std::vector<double> ring_radii;  // m, ascending
};
InterfacePlanes interface_planes(const std::vector<geometry::Pipe2>& pipes);

}  // namespace frostwall::geometry
