// Moment-corrected pair weights for irregular (graded) particle clouds.
//
// The renormalised pair weights are exact for quadratic fields on a lattice,
// where the kernel sums' odd moments vanish by symmetry. On an irregular
// cloud they do not: the first moment m_i = sum_j W_ij (x_j - x_i) leaves a
// Laplacian error of order |grad T| m_i / h for a *linear* field, which does
// not fall as the spacing is refined (measured on the graded shaft cloud:
// 0.1-0.4 per unit gradient with 5 cm particles). A tensor-corrected
// Laplacian fixes that but uses a gradient estimate and loses the
// antisymmetric pair flux, so energy would no longer be exact.
//
// Here the symmetric pair weights W_ij = V_i G_ij (= W_ji) are changed so
// that for every free particle i with a full neighbourhood
//     sum_j W_ij (x_j - x_i) = 0                        (first moment)
//     sum_j W_ij |x_j - x_i|^2 = Dim V_i                 (second moment, trace)
// which makes sum_j G_ij 2 (T_j - T_i) exact for linear fields and for
// |x|^2 (the factor 2 is the pair conductivity 2k of equal k): the scalar
// renormalisation's condition, now with the first moment. The change is the
// least-squares one in relative terms, sum over pairs of (dW/W)^2: with
// multipliers lambda_i (Dim) and mu_i,
//     dW_ij = W_ij^2 [ (lambda_i - lambda_j) . d_ij + (mu_i + mu_j) |d_ij|^2 ],
// linear in the multipliers, so one sparse symmetric solve sets every
// moment. dW_ij is the same seen from i or from j, so V_i G_ij = V_j G_ji
// still holds: the flux stays antisymmetric and energy exact. A mirror
// image carries its source's multipliers mapped through the mirror
// (lambda -> A lambda), which keeps that symmetry across the planes.
// Measured on the graded shaft cloud: every weight stays positive (new/old
// 0.48 .. 2.5; a least-squares change in absolute terms, or also fixing the
// anisotropic part of the second moment, made some weights negative, i.e.
// heat flowing from cold to hot). The anisotropic second moment is left as
// it is: a few per cent on a CVT cloud, with zero mean.
// Particles whose neighbourhood is one-sided (a free surface with neither
// mirror nor fixed particles beyond) keep their weights: no positive
// weights could make their first moment vanish.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "sph/laplacian.hpp"
#include "sph/two_level_solver.hpp"

namespace frostwall::sph {

using particles::Vec;

// The system for the multipliers, one block row (lambda, mu, scaled by the
// particle's length) per corrected particle.
template <int Dim>
struct MomentSystem {
  static constexpr int unknowns = Dim + 1;
  // Shifts, rotations, the dilation, a common mu (moment_correction.cpp).
  static constexpr int modes = Dim + Dim * (Dim - 1) / 2 + 2;
  std::vector<long> slot;  // per free particle: its block row, -1 = weights kept
  BlockMatrix<unknowns> K;
  Eigen::VectorXd rhs;
  std::vector<Eigen::Matrix<double, unknowns, modes>> near_null;  // per block row
};

struct MomentCorrectionReport {
  std::size_t corrected = 0;     // free particles whose moments were set
  double smallest_factor = 1.0;  // min over pairs of the new weight / the old
  double largest_factor = 1.0;
  double residual = 0.0;  // largest moment error left, relative
};

// position: the free particles' (their first n_free entries are used);
// pair_vector[e] = x_j - x_i for pair e (the image's position for an image
// pair); to_image[e] the linear part of the isometry that made that image
// (identity for a real neighbour); length_scale[i] a length of particle i
// (its h), for conditioning.
template <int Dim>
MomentCorrectionReport correct_pair_moments(LaplacianPairs& pairs, const std::vector<Vec<Dim>>& position,
                                            const std::vector<double>& volume, const std::vector<Vec<Dim>>& pair_vector,
                                            const std::vector<Eigen::Matrix<double, Dim, Dim>>& to_image,
                                            const std::vector<double>& length_scale);

// The pieces of correct_pair_moments (apart for the solver's tests).
template <int Dim>
MomentSystem<Dim> moment_system(const LaplacianPairs& pairs, const std::vector<Vec<Dim>>& position,
                                const std::vector<double>& volume, const std::vector<Vec<Dim>>& pair_vector,
                                const std::vector<Eigen::Matrix<double, Dim, Dim>>& to_image,
                                const std::vector<double>& length_scale);
// Two-level CG to 1e-8; a sparse LDLT if that fails.
template <int Dim>
Eigen::VectorXd solve_moment_system(const MomentSystem<Dim>& system, TwoLevelReport* report = nullptr);

}  // namespace frostwall::sph
