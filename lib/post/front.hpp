// The frozen front of a plain-geometry problem: where the liquid fraction
// crosses 0.5, measured from the cooled face along its inward normal.
#pragma once

#include <optional>
#include <vector>

#include "geometry/rectangle.hpp"
#include "particles/vec.hpp"

namespace frostwall::post {

// Particles are binned into rows parallel to the face (the lattice rows),
// the liquid fraction averaged per row, and the first crossing of 0.5 from
// the face (frozen, f = 0) outward found by linear interpolation between
// row centres. nullopt if no row reaches f >= 0.5 (all frozen).
std::optional<double> frozen_front(const std::vector<particles::Vec<2>>& position,
                                   const std::vector<double>& liquid_fraction, std::size_t n_free,
                                   const geometry::CooledFace& face);

}  // namespace frostwall::post
