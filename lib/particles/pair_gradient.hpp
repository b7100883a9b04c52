// A field's gradient at each free particle from its pairs alone: the
// weighted least-squares plane through the particle's value, weights the
// pair weights G_e, over the pairs' vectors (PairWeights::vector). Exact
// for a linear field even on a one-sided support (beside a wall); pairs
// to a NaN value (no such field there) are skipped. Needs the pairs built
// with their vectors (sph::LaplacianOptions::keep_vectors); 2-D.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "particles/pair_weights.hpp"
#include "particles/parallel.hpp"

namespace frostwall::particles {

// gradient[2 i], gradient[2 i + 1] for every free particle i (0 where the
// neighbours do not span the plane).
inline void pair_gradient(const PairWeights& P, const std::vector<double>& field, std::vector<double>& gradient) {
  if (P.vector.size() != 2 * P.pairs()) throw std::logic_error("pair_gradient: the pairs carry no vectors");
  gradient.assign(2 * P.n_free, 0.0);
  for_each_particle(P.n_free, [&](std::size_t i) {
    double m00 = 0.0, m01 = 0.0, m11 = 0.0, b0 = 0.0, b1 = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const double value = field[P.column[e]];
      if (std::isnan(value)) continue;
      const double w = P.weight[e], x = P.vector[2 * e], y = P.vector[2 * e + 1], d = value - field[i];
      m00 += w * x * x, m01 += w * x * y, m11 += w * y * y, b0 += w * d * x, b1 += w * d * y;
    }
    const double det = m00 * m11 - m01 * m01;
    if (det > 1e-14 * (m00 * m11 + m01 * m01)) {
      gradient[2 * i] = (m11 * b0 - m01 * b1) / det;
      gradient[2 * i + 1] = (m00 * b1 - m01 * b0) / det;
    }
  });
}

}  // namespace frostwall::particles
