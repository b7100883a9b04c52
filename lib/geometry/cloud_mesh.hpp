// The triangles of a particle cloud: its Delaunay triangulation without the
// long slivers that cross holes (pipe discs, the excavation, pores) and
// concave parts of the hull. The isolines of the post-processing and the
// cells of the VTK files are drawn on it, so ParaView's Contour filter and
// the report's fronts see the same piecewise-linear field.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::geometry {

using Triangle = std::array<std::uint32_t, 3>;  // point indices, counterclockwise

// Triangles whose longest edge exceeds the largest limit of their three
// corners are dropped (max_edge_at: one limit for all points, or one per
// point; an infinite limit keeps the whole triangulation). Coincident
// points are triangulated once. Throws std::invalid_argument on non-finite
// points, a limit not > 0, or more than 2^32 points.
std::vector<Triangle> cloud_triangles(const std::vector<particles::Vec<2>>& points,
                                      const std::vector<double>& max_edge_at);

inline std::vector<Triangle> cloud_triangles(const std::vector<particles::Vec<2>>& points,
                                             double max_edge = std::numeric_limits<double>::infinity()) {
  return cloud_triangles(points, std::vector<double>{max_edge});
}

}  // namespace frostwall::geometry
