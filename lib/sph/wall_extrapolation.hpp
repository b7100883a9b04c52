// Temperatures of fixed particles beyond a wall, by antisymmetric
// extension: T_j = 2 T_wall - T(reflection_j) (symmetric for an insulated
// wall, below), with T at the reflection
// point from the free particles around it by moving least squares, linear
// (exact for a linear field, so a wall with a straight temperature profile
// is seen exactly where it is). Weights are computed once.
#pragma once

#include <cstdint>
#include <vector>

#include "sph/kernel.hpp"
#include "particles/particle_set.hpp"
#include "sph/smoothing_lengths.hpp"

namespace frostwall::sph {

using particles::ParticleSet;

struct WallExtrapolation {
  // Per fixed particle (index - n_free): its weights over free particles;
  // an empty row means "on the wall": it holds T_wall.
  std::vector<std::size_t> row_start;
  std::vector<std::uint32_t> column;
  std::vector<double> weight;
  double value(std::size_t fixed_index, const std::vector<double>& field) const {
    double v = 0.0;
    for (std::size_t e = row_start[fixed_index]; e < row_start[fixed_index + 1]; ++e) v += weight[e] * field[column[e]];
    return v;
  }
  bool on_wall(std::size_t fixed_index) const { return row_start[fixed_index] == row_start[fixed_index + 1]; }
};

// insulated_walls[b]: boundary b conducts no heat. Its wall holds 0 and its
// rows carry the negated weights, so T_j = 2 * 0 + T(reflection_j): the
// symmetric extension, in the same arithmetic as the others. A reflection
// that is a particle (a lattice mirrored across a face between rows) takes
// that particle's value exactly.
template <int Dim>
WallExtrapolation build_wall_extrapolation(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                           const SmoothingLengths& h, const std::vector<bool>& insulated_walls = {});

}  // namespace frostwall::sph
