// A conduction operator on a fixed particle cloud as weights on pairs, in
// CSR over the free particles: dH_i/dt = sum_e weight[e] k_ij (T_j - T_i)
// for the pairs e = (i, column[e]), k_ij the pair conductivity (2k for
// equal k). SPH fills it from kernel gradients (sph/laplacian.hpp), PD from
// thermal bonds (pd/conduction_bonds.hpp); the thermal model runs on it
// whichever made it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frostwall::particles {

struct PairWeights {
  std::size_t n_free = 0;
  std::vector<std::size_t> row_start;  // n_free + 1
  std::vector<std::uint32_t> column;   // real particle index (>= n_free: fixed)
  std::vector<double> weight;          // G_ij
  // Squared direction cosines of r_ij per pair (Dim values), kept only for
  // anisotropic soils, whose pair factor depends on the pair's direction.
  std::vector<double> direction2;
  // x_j - x_i per pair (Dim values; j as the pair sees it, a mirror image
  // or the particle), kept only when asked (LaplacianOptions::keep_vectors).
  std::vector<double> vector;
  int dim = 2;
  std::vector<double> renormalisation;  // c_i per free particle (1 for plain)
  // Moment correction (graded clouds): particles corrected, and the range of
  // new weight / old weight over the pairs.
  std::size_t moments_corrected = 0;
  double smallest_weight_factor = 1.0, largest_weight_factor = 1.0;

  std::size_t pairs() const { return column.size(); }
};

}  // namespace frostwall::particles
