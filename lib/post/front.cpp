#include "post/front.hpp"

#include <cmath>

namespace frostwall::post {

std::optional<double> frozen_front(const std::vector<particles::Vec<2>>& position,
                                   const std::vector<double>& liquid_fraction, std::size_t n_free,
                                   const geometry::CooledFace& face) {
  const double d = face.spacing;
  std::vector<double> sum, count, depth_sum;
  for (std::size_t i = 0; i < n_free; ++i) {
    const double depth = (position[i] - face.origin).dot(face.inward_normal);
    const auto row = static_cast<std::size_t>(std::lround(depth / d));
    if (row >= sum.size()) {
      sum.resize(row + 1, 0.0);
      count.resize(row + 1, 0.0);
      depth_sum.resize(row + 1, 0.0);
    }
    sum[row] += liquid_fraction[i];
    count[row] += 1.0;
    depth_sum[row] += depth;
  }
  // Row 0 is the face itself, held below freezing: f = 0. A graded cloud has
  // no rows: bins one (finest) spacing wide, each at its particles' mean
  // depth, from the face (f = 0 at depth 0) on.
  double prev_depth = 0.0, prev_f = 0.0;
  for (std::size_t row = face.lattice_rows ? 1 : 0; row < sum.size(); ++row) {
    if (count[row] == 0.0) continue;
    const double f = sum[row] / count[row];
    const double depth = face.lattice_rows ? row * d : depth_sum[row] / count[row];
    if (f >= 0.5) return prev_depth + (0.5 - prev_f) / (f - prev_f) * (depth - prev_depth);
    prev_depth = depth;
    prev_f = f;
  }
  return std::nullopt;
}

}  // namespace frostwall::post
