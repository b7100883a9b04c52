// A rectangle [0, width] x [0, height] on a lattice. A fixed-temperature
// side has its face on a particle row and ceil(2h/spacing) fixed layers
// from the face outwards (the kernel support of the first free row is
// full); an adiabatic side is a mirror plane halfway between two rows.
// The spacing along each axis is adjusted (slightly) so both sides fit.
#pragma once

#include <array>
#include <string>

#include "geometry/scene.hpp"
#include "project/project.hpp"

namespace frostwall::geometry {

struct RectangleScene : Scene {
  std::array<double, 2> spacing{};  // along x and y, after fitting
};

RectangleScene build_rectangle(const project::Rectangle& rect, double spacing, double h);

// The side the problem is cooled from (the coldest fixed side at t = 0):
// fronts are measured from its face along its inward normal.
struct CooledFace {
  std::string side;
  sph::Vec<2> origin;         // a point on the face
  sph::Vec<2> inward_normal;  // unit, into the rectangle
  double spacing = 0.0;       // lattice spacing along the normal
};
std::optional<CooledFace> cooled_face(const project::Rectangle& rect, const RectangleScene& scene);

}  // namespace frostwall::geometry
