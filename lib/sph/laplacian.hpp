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

#include "project/project.hpp"
#include "sph/kernel.hpp"
#include "sph/particle_set.hpp"
#include "sph/smoothing_lengths.hpp"

namespace frostwall::sph {

struct LaplacianPairs {
  std::size_t n_free = 0;
  std::vector<std::size_t> row_start;     // n_free + 1
  std::vector<std::uint32_t> column;      // real particle index (>= n_free: fixed)
  std::vector<double> weight;             // G_ij
  // Squared direction cosines of r_ij per pair (Dim values), kept only for
  // anisotropic soils, whose pair factor depends on the pair's direction.
  std::vector<double> direction2;
  int dim = 2;
  std::vector<double> renormalisation;    // c_i per free particle (1 for plain)
  // Moment correction (graded clouds): particles corrected, and the range of
  // new weight / old weight over the pairs.
  std::size_t moments_corrected = 0;
  double smallest_weight_factor = 1.0, largest_weight_factor = 1.0;

  std::size_t pairs() const { return column.size(); }
};

struct LaplacianOptions {
  SmoothingLengths h;  // one h (lattice) or one per particle (graded: pairs use (h_i + h_j) / 2)
  project::LaplacianForm form = project::LaplacianForm::renormalised;
  bool keep_directions = false;  // anisotropic soil
  // Graded clouds: make the renormalised weights exact for every quadratic
  // field (moment_correction.hpp); a lattice is exact without it.
  bool correct_moments = false;
};

template <int Dim>
LaplacianPairs build_laplacian_pairs(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                     const LaplacianOptions& options);

// Mirror images of real particles within reach (2h) of a free particle,
// through every composition of the mirror planes that still reaches the
// domain (corners, wedge apex). source[k] is the real particle imaged.
template <int Dim>
struct MirrorImages {
  std::vector<Vec<Dim>> position;
  std::vector<std::uint32_t> source;
  // The linear part A of the isometry that made each image (y = A x + b):
  // vectors and tensors at the source map to the image through it.
  std::vector<Eigen::Matrix<double, Dim, Dim>> linear;
};
// own_reach (optional, one per particle): an image of particle j further
// than own_reach[j] beyond a plane is not wanted either (a graded cloud's
// fine particles need images only a few of their own spacings out).
template <int Dim>
MirrorImages<Dim> mirror_images(const ParticleSet<Dim>& particles, double reach,
                                const std::vector<double>& own_reach = {});

}  // namespace frostwall::sph
