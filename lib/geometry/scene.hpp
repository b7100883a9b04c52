// What geometry hands to the solver: the particle cloud (free particles,
// fixed-temperature particles, mirror planes) and the boundaries the fixed
// particles belong to.
#pragma once

#include <string>
#include <vector>

#include "particles/particle_set.hpp"
#include "geometry/boundary.hpp"

namespace frostwall::geometry {

struct Scene {
  virtual ~Scene() = default;
  particles::ParticleSet<2> particles;
  std::vector<geometry::FixedTemperatureBoundary> boundaries;
  std::vector<std::string> notes;  // e.g. spacing adjusted to fit the sides
};

}  // namespace frostwall::geometry
