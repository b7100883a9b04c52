#include "pd/conduction_bonds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "particles/cell_list.hpp"
#include "particles/mirror_images.hpp"
#include "particles/parallel.hpp"

namespace frostwall::pd {

double micro_conductivity_per_k(double horizon) { return 6.0 / (std::numbers::pi * std::pow(horizon, 3)); }

particles::PairWeights build_conduction_bonds(const particles::ParticleSet<2>& P,
                                              const ConductionBondOptions& options) {
  const double delta = options.horizon;
  if (!(delta > P.coarsest_spacing())) throw std::invalid_argument("pd: the horizon must be larger than the spacing");
  // A neighbour's cell reaches half a spacing beyond its centre.
  const double reach = delta + 0.5 * P.coarsest_spacing();
  const auto images = particles::mirror_images(P, reach);
  std::vector<particles::Vec<2>> points = P.position;
  std::vector<std::uint32_t> source(P.size());
  for (std::size_t j = 0; j < P.size(); ++j) source[j] = static_cast<std::uint32_t>(j);
  points.insert(points.end(), images.position.begin(), images.position.end());
  source.insert(source.end(), images.source.begin(), images.source.end());
  const particles::CellList<2> cells(points, reach);

  // Bond weight w_ij = kappa/(2k) V_j beta_ij / |xi|: the model multiplies
  // by k_ij = 2k. beta_ij: the share of j's cell inside the horizon.
  const double kappa_half = 0.5 * micro_conductivity_per_k(delta);
  // visit(j, r, w) for every bond of i, its own images included: they
  // carry no flux (T_i - T_i) but belong to the neighbourhood whose moment
  // sets c_i (a particle next to a mirror would otherwise count a hole).
  auto for_each_bond = [&](std::size_t i, auto&& visit) {
    cells.for_each_within(P.position[i], reach, [&](std::uint32_t k, double r) {
      const std::uint32_t j = source[k];
      if (r == 0.0) return;  // itself
      const double dx = 0.5 * (P.spacing_of(i) + P.spacing_of(j));
      double share = r <= delta ? 1.0 : 0.0;
      if (options.partial_volumes) share = std::clamp((delta + 0.5 * dx - r) / dx, 0.0, 1.0);
      if (share <= 0.0) return;
      visit(j, r, kappa_half * P.volume[j] * share / r);
    });
  };

  const std::size_t n = P.n_free;
  particles::PairWeights pairs;
  pairs.dim = 2;
  pairs.n_free = n;
  pairs.renormalisation.assign(n, 1.0);
  std::vector<std::size_t> count(n, 0);
  particles::for_each_particle(n, [&](std::size_t i) {
    double moment = 0.0;  // sum_j w_ij |xi|^2: Dim for an exact operator
    for_each_bond(i, [&](std::uint32_t j, double r, double w) {
      moment += w * r * r;
      if (j != i) ++count[i];
    });
    if (count[i] == 0 || !(moment > 0.0)) throw std::runtime_error("pd: a particle has no thermal bond");
    if (options.renormalised) pairs.renormalisation[i] = 2.0 / moment;
  });
  pairs.row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) pairs.row_start[i + 1] = pairs.row_start[i] + count[i];
  pairs.column.resize(pairs.row_start[n]);
  pairs.weight.resize(pairs.row_start[n]);
  const auto& c = pairs.renormalisation;
  particles::for_each_particle(n, [&](std::size_t i) {
    std::size_t e = pairs.row_start[i];
    for_each_bond(i, [&](std::uint32_t j, double, double w) {
      if (j == i) return;
      // A fixed neighbour has no factor of its own: it takes i's.
      const double cj = j < n ? c[j] : c[i];
      pairs.column[e] = j;
      pairs.weight[e++] = w * 0.5 * (c[i] + cj);
    });
  });
  return pairs;
}

}  // namespace frostwall::pd
