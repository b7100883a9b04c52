// The Delaunay triangulation of a point set as plain indices: its faces and
// its edges. One source (triangulation.cpp) instantiates CGAL's
// triangulation for them, so their users compile without CGAL's headers.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::geometry {

// Each finite face as three point indices, counterclockwise, in CGAL's
// face order. Coincident points are triangulated once (the later ones are
// in no face). Requires fewer than 2^32 finite points.
std::vector<std::array<std::uint32_t, 3>> delaunay_faces(const std::vector<particles::Vec<2>>& points);

// Each finite edge once, as two point indices.
std::vector<std::array<std::uint32_t, 2>> delaunay_edges(const std::vector<particles::Vec<2>>& points);

}  // namespace frostwall::geometry
