// The SPH conduction stencil, built once: for every free particle i, its
// neighbours j (real particles, or mirror images folded back onto their
// source) with the stored pair weight
//     G_ij = -V_j (r_ij . grad_i W_ij) / (|r_ij|^2 + eta^2) * s_ij  >= 0,
// so that div(k grad T)_i = sum_j G_ij k_ij (T_j - T_i), with k_ij the
// pair conductivity (harmonic or arithmetic "sum" form, 2k for equal k).
//
// s_ij is the symmetric second-moment renormalisation (c_i + c_j)/2 with
// c_i = -Dim / sum_j V_j F_ij |r_ij|^2: it makes the operator exact for
// quadratic fields on a lattice (the plain form keeps an O(1) error at
// fixed h/spacing) while keeping the flux antisymmetric, so energy is exact.
// On a graded cloud each particle has its own h_i; F_ij uses the pair's
// h_ij = (h_i + h_j)/2, which keeps V_i G_ij = V_j G_ji.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "project/numerics.hpp"
#include "sph/kernel.hpp"
#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"
#include "sph/smoothing_lengths.hpp"

namespace frostwall::sph {

using particles::ParticleSet;

// The SPH weights fill the engines' shared pair structure.
using LaplacianPairs = particles::PairWeights;

struct LaplacianOptions {
  SmoothingLengths h;  // one h (lattice) or one per particle (graded: pairs use (h_i + h_j) / 2)
  project::LaplacianForm form = project::LaplacianForm::renormalised;
  bool keep_directions = false;  // anisotropic soil
  // Graded clouds: make the renormalised weights exact for every quadratic
  // field (moment_correction.hpp); a lattice is exact without it.
  bool correct_moments = false;
  // Store each pair's vector x_j - x_i (j as the pair sees it: a mirror
  // image or the particle): the gradients a second-order advection needs.
  bool keep_vectors = false;
};

template <int Dim>
LaplacianPairs build_laplacian_pairs(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                     const LaplacianOptions& options);

}  // namespace frostwall::sph
