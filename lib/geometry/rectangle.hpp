// A rectangle [0, width] x [0, height] on a lattice. A fixed-temperature
// side has its face on a particle row and ceil(2h/spacing) fixed layers
// from the face outwards (the kernel support of the first free row is
// full); an adiabatic side is a mirror plane halfway between two rows, or,
// with a hydraulic head, lies there with fixed layers beyond it that copy
// their mirror images' temperatures (an insulated boundary: no heat is
// conducted through it, water flows through it).
// The spacing along each axis is adjusted (slightly) so both sides fit.
#pragma once

#include <array>
#include <string>

#include "geometry/scene.hpp"
#include "geometry/size_field.hpp"
#include "project/project.hpp"

namespace frostwall::geometry {

struct RectangleScene : Scene {
  std::array<double, 2> spacing{};  // along x and y, after fitting
};

RectangleScene build_rectangle(const project::Rectangle& rect, double spacing, double h);

// Graded placement (numerics.placement "graded"): `finest` at the cooled
// face (the coldest fixed side), band_coarsening * finest within band_width
// of it (default a third of the rectangle across), growing by (growth - 1)
// per metre beyond; at most coarsening * finest and half the rectangle's
// smaller side (so a strip keeps a few particles across).
SizeField rectangle_size_field(const project::Rectangle& rect, double finest, const project::Grading& grading);

// Free particles from a CVT of the rectangle (graded_placement.hpp);
// adiabatic sides are mirror planes as on the lattice; a fixed side is held
// by the free particles' reflections across it (within 2.2 h), each the
// antisymmetric image of its source, so the face lies halfway between a
// particle and its image; beyond two fixed sides (a corner) the twice
// reflected particles hold the first side's temperature.
RectangleScene build_graded_rectangle(const project::Rectangle& rect, const SizeField& size, double smoothing_ratio);

// The side the problem is cooled from (the coldest fixed side at t = 0):
// fronts are measured from its face along its inward normal.
struct CooledFace {
  std::string side;
  particles::Vec<2> origin;         // a point on the face
  particles::Vec<2> inward_normal;  // unit, into the rectangle
  double spacing = 0.0;             // lattice spacing along the normal (graded: the finest)
  bool lattice_rows = true;         // particles in rows parallel to the face (false: a graded cloud)
};
std::optional<CooledFace> cooled_face(const project::Rectangle& rect, const RectangleScene& scene);

}  // namespace frostwall::geometry
