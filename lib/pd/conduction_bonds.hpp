// Peridynamic heat conduction (the PD paper; Bobaru & Duangpanya 2010): a
// thermal bond joins every pair of particles closer than the horizon delta
// and carries
//     q_ij = kappa (T_j - T_i) / |xi_ij| V_j,   kappa = 6 k / (pi t delta^3)
// (2-D, t = 1 per metre of depth), so that rho c dT_i/dt = sum_j q_ij.
// Written as the engines' shared pair weights (particles/pair_weights.hpp:
// rate = sum weight k_ij (T_j - T_i), k_ij = 2k for equal ends), so the
// thermal model, its integrators and its energy bookkeeping run on it
// unchanged; the enthalpy form and the phase law are theirs. A bond's
// conductivity comes from its two ends (harmonic mean of the liquid,
// frozen or in-between values), as the model's pairs do.
//
// Quadrature: one point per neighbour overestimates the conductivity by
// 2-5 % at delta = 3 spacings (physics.md). Two corrections, both kept
// antisymmetric so energy stays exact:
//  - partial volumes: a neighbour whose cell straddles the horizon counts
//    with the share of its cell inside (linear in the distance);
//  - renormalised (default): each particle's bonds scaled by
//    c_i = Dim / sum_j w_ij |xi_ij|^2, the pair by (c_i + c_j) / 2, which
//    makes the operator exact for quadratic fields wherever the neighbourhood
//    is complete (mirror images at symmetry planes, fixed layers beyond a
//    held face). "plain" keeps the paper's kappa as it is.
#pragma once

#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"

namespace frostwall::pd {

struct ConductionBondOptions {
  double horizon = 0.0;  // delta, m
  bool renormalised = true;
  bool partial_volumes = true;
};

// Bonds of every free particle to the real particles (free or fixed) and
// mirror images within the horizon; images fold onto their source. Throws
// std::invalid_argument for a horizon not larger than the spacing.
particles::PairWeights build_conduction_bonds(const particles::ParticleSet<2>& particles,
                                              const ConductionBondOptions& options);

// kappa / (k t) of the 2-D model: 6 / (pi delta^3), per metre of depth.
double micro_conductivity_per_k(double horizon);

}  // namespace frostwall::pd
