// Steady Darcy flow on a particle cloud, on the same pairs as the heat
// (particles::PairWeights). With the potential psi = K_sat h (m^2/s; h the
// head, K_sat the unfrozen hydraulic conductivity) the flux is
// q = -k_r grad psi, and div q = 0 becomes, for every free particle i,
//     sum_j G_ij k_ij (psi_j - psi_i) = 0,
// k_ij the pair's relative permeability (4 k_i k_j / (k_i + k_j): 2k for
// equal k, the conduction operator's convention). V_i G_ij = V_j G_ji, so
// the system is symmetric; it is factored (sparse LDL^T) rather than
// iterated, because frozen ground makes k_r span six orders of magnitude
// (Eigen's simplicial LDL^T, CHOLMOD's supernodal LL^T on large clouds).
// Fixed particles either hold a potential (the far field: psi = -q_inf . x
// for a regional flux q_inf) or carry no flow (pipes): their pairs drop out.
//
// The pair fluxes Q_ij = V_i G_ij k_ij (psi_i - psi_j) (m^2/s per metre
// of depth, i to j) balance at every free particle to the solver's
// round-off: the discrete flow is exactly divergence-free, which is what
// lets the heat it carries (thermal advection) conserve energy.
#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "particles/pair_weights.hpp"

namespace frostwall::groundwater {

struct DarcySolveReport {
  double largest_imbalance = 0.0;  // max_i |sum_j Q_ij| / the largest |Q_ij|
  bool factored = false;
};

class DarcyCloud {
 public:
  // `fixed_potential[f]` for fixed particle n_free + f: its potential, or
  // NaN for no flow through it.
  DarcyCloud(const particles::PairWeights& pairs, std::vector<double> volume, std::vector<double> fixed_potential);
  ~DarcyCloud();

  // Solves with relative permeability k_r per particle (free and fixed).
  DarcySolveReport solve(const std::vector<double>& relative_permeability);

  // Potential of every particle (fixed ones: given; no-flow ones: NaN).
  const std::vector<double>& potential() const { return psi_; }
  // Q_e of every stored pair e = (i, column[e]), from i to column[e];
  // 0 for pairs to a no-flow particle.
  const std::vector<double>& pair_flux() const { return flux_; }
  // The volume flow into the free particles from the fixed ones holding a
  // potential (m^2/s per metre of depth; in minus out; gross: in only).
  double inflow_from_boundary(bool gross = false) const;

 private:
  struct Factor;
  const particles::PairWeights& pairs_;
  std::vector<double> volume_, fixed_;
  std::vector<double> psi_, flux_;
  std::unique_ptr<Factor> factor_;
};

}  // namespace frostwall::groundwater
