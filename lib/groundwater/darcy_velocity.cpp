#include "groundwater/darcy_velocity.hpp"

#include "particles/pair_gradient.hpp"

namespace frostwall::groundwater {

std::vector<particles::Vec<2>> darcy_flux_at_particles(const particles::PairWeights& pairs,
                                                       const std::vector<double>& potential,
                                                       const std::vector<double>& k_r) {
  std::vector<double> gradient;
  particles::pair_gradient(pairs, potential, gradient);
  std::vector<particles::Vec<2>> q(pairs.n_free);
  for (std::size_t i = 0; i < q.size(); ++i) q[i] = -k_r[i] * particles::Vec<2>(gradient[2 * i], gradient[2 * i + 1]);
  return q;
}

}  // namespace frostwall::groundwater
