// Smoothing lengths of a particle cloud: one for a lattice, one per particle
// for a graded cloud (h_i = smoothing_ratio * local spacing). A pair uses
// the mean h_ij = (h_i + h_j) / 2: symmetric in i and j, so the pair weight
// V_i G_ij = V_j G_ji stays symmetric and the pair flux antisymmetric
// (energy exact), and a pair interacts when r < 2 h_ij = h_i + h_j.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "particles/particle_set.hpp"

namespace frostwall::sph {

using particles::ParticleSet;

struct SmoothingLengths {
  double uniform = 0.0;
  std::vector<double> per_particle;  // empty: every particle has `uniform`

  SmoothingLengths() = default;
  SmoothingLengths(double h) : uniform(h) {}  // a lattice (implicit: old call sites pass h)
  template <int Dim>
  static SmoothingLengths of_particles(const ParticleSet<Dim>& particles, double smoothing_ratio) {
    SmoothingLengths s(smoothing_ratio * particles.spacing);
    for (double d : particles.local_spacing) s.per_particle.push_back(smoothing_ratio * d);
    return s;
  }

  bool varies() const { return !per_particle.empty(); }
  double of(std::size_t i) const { return per_particle.empty() ? uniform : per_particle[i]; }
  double pair(std::size_t i, std::size_t j) const { return per_particle.empty() ? uniform : 0.5 * (of(i) + of(j)); }
  double largest() const {
    return per_particle.empty() ? uniform : *std::max_element(per_particle.begin(), per_particle.end());
  }
  double smallest() const {
    return per_particle.empty() ? uniform : *std::min_element(per_particle.begin(), per_particle.end());
  }
};

}  // namespace frostwall::sph
