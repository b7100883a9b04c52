#include "sph/moment_correction.hpp"

#include <Eigen/Sparse>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <stdexcept>

namespace frostwall::sph {

namespace {

// Multipliers per particle: lambda (Dim components) and mu.
template <int Dim>
constexpr int unknowns = Dim + 1;

template <int Dim>
using Features = Eigen::Matrix<double, unknowns<Dim>, 1>;

// (d / l, |d|^2 / l^2): the moments a pair adds to its row, and how the
// row's own multipliers change the pair (l scales them to order one).
template <int Dim>
Features<Dim> features(const Vec<Dim>& d, double l) {
  Features<Dim> f;
  f.template head<Dim>() = d / l;
  f[Dim] = d.squaredNorm() / (l * l);
  return f;
}

// K is symmetric positive definite. Conjugate gradients with an incomplete
// Cholesky preconditioner take about 120 iterations (to 1e-8) on a graded shaft
// wedge (25 000 unknowns) and cost half of a sparse LDLT, whose fill on
// these 3x3-block rows is large; the LDLT stays as the fallback.
Eigen::VectorXd solve_moment_system(const Eigen::SparseMatrix<double>& K_columns, const Eigen::VectorXd& rhs) {
  // Row-major with both triangles: Eigen then runs the product on all
  // OpenMP threads.
  const Eigen::SparseMatrix<double, Eigen::RowMajor> K = K_columns;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::AMDOrdering<int>>>
      cg;
  cg.setTolerance(1e-8);
  cg.setMaxIterations(1000);
  cg.compute(K);
  if (cg.info() == Eigen::Success) {
    Eigen::VectorXd z = cg.solve(rhs);
    if (cg.info() == Eigen::Success) return z;
  }
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K_columns);
  if (solver.info() != Eigen::Success) throw std::runtime_error("moment correction: the moment system is singular");
  return solver.solve(rhs);
}

}  // namespace

template <int Dim>
MomentCorrectionReport correct_pair_moments(LaplacianPairs& pairs, const std::vector<double>& volume,
                                            const std::vector<Vec<Dim>>& pair_vector,
                                            const std::vector<Eigen::Matrix<double, Dim, Dim>>& to_image,
                                            const std::vector<double>& length_scale) {
  constexpr int P = unknowns<Dim>;
  const std::size_t n = pairs.n_free;
  MomentCorrectionReport report;

  // Which particles get their moments set: those whose neighbours surround
  // them (first moment well below the first absolute moment).
  std::vector<long> slot(n, -1);
  long rows = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec<Dim> m = Vec<Dim>::Zero();
    double absolute = 0.0;
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      m += pairs.weight[e] * pair_vector[e];
      absolute += pairs.weight[e] * pair_vector[e].norm();
    }
    if (absolute > 0.0 && m.norm() < 0.2 * absolute) slot[i] = rows++;
  }
  report.corrected = static_cast<std::size_t>(rows);
  if (rows == 0) return report;

  // The other end's features: its vector to us is -u with u = A^T d (A the
  // image's mirror map), |u| = |d|.
  auto far_features = [&](std::size_t e, std::uint32_t j) {
    const Vec<Dim> u = to_image[e].transpose() * pair_vector[e];
    Features<Dim> f = features<Dim>(u, length_scale[j]);
    f.template head<Dim>() *= -1.0;
    return f;
  };

  // dW_e = W_e^2 (psi_i . z_i + psi_j . z_j): least squares of the relative
  // changes dW/W (a pair's weight moves in proportion to its size, so the
  // small weights at the rim of the kernel keep their sign). Row i:
  // sum_e phi_e (W_e + dW_e) = target_i.
  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows * P);
  for (std::size_t i = 0; i < n; ++i) {
    if (slot[i] < 0) continue;
    const long r = slot[i] * P;
    const double l = length_scale[i];
    Eigen::Matrix<double, P, P> diagonal = Eigen::Matrix<double, P, P>::Zero();
    Features<Dim> moment = Features<Dim>::Zero();
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      const double W = volume[i] * pairs.weight[e];
      const Features<Dim> phi = features<Dim>(pair_vector[e], l);
      moment += W * phi;
      diagonal += W * W * phi * phi.transpose();
      const std::uint32_t j = pairs.column[e];
      if (j >= n || slot[j] < 0) continue;
      const Features<Dim> psi = far_features(e, j);
      const long c = slot[j] * P;
      for (int a = 0; a < P; ++a)
        for (int b = 0; b < P; ++b) triplets.emplace_back(r + a, c + b, W * W * phi[a] * psi[b]);
    }
    for (int a = 0; a < P; ++a)
      for (int b = 0; b < P; ++b) triplets.emplace_back(r + a, r + b, diagonal(a, b));
    Features<Dim> target = Features<Dim>::Zero();
    target[Dim] = Dim * volume[i] / (l * l);
    rhs.segment<P>(r) = target - moment;
  }
  Eigen::SparseMatrix<double> K(rows * P, rows * P);
  K.setFromTriplets(triplets.begin(), triplets.end());
  // A whisker of regularisation: without fixed particles a common shift of
  // all lambda changes no pair between free particles.
  double largest = 0.0;
  for (long k = 0; k < K.rows(); ++k) largest = std::max(largest, K.coeff(k, k));
  for (long k = 0; k < K.rows(); ++k) K.coeffRef(k, k) += 1e-12 * largest;
  const Eigen::VectorXd z = solve_moment_system(K, rhs);

  // The new weights, and how far they moved.
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      double change = 0.0;
      if (slot[i] >= 0) change += features<Dim>(pair_vector[e], length_scale[i]).dot(z.segment<P>(slot[i] * P));
      const std::uint32_t j = pairs.column[e];
      if (j < n && slot[j] >= 0) change += far_features(e, j).dot(z.segment<P>(slot[j] * P));
      const double factor = 1.0 + volume[i] * pairs.weight[e] * change;
      pairs.weight[e] *= factor;
      report.smallest_factor = std::min(report.smallest_factor, factor);
      report.largest_factor = std::max(report.largest_factor, factor);
    }

  // What is left of the moment errors, relative to the second moment.
  for (std::size_t i = 0; i < n; ++i) {
    if (slot[i] < 0) continue;
    Features<Dim> moment = Features<Dim>::Zero();
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e)
      moment += volume[i] * pairs.weight[e] * features<Dim>(pair_vector[e], length_scale[i]);
    const double unit = Dim * volume[i] / (length_scale[i] * length_scale[i]);
    moment[Dim] -= unit;
    report.residual = std::max(report.residual, moment.cwiseAbs().maxCoeff() / unit);
  }
  return report;
}

template MomentCorrectionReport correct_pair_moments<2>(LaplacianPairs&, const std::vector<double>&,
                                                        const std::vector<Vec<2>>&,
                                                        const std::vector<Eigen::Matrix<double, 2, 2>>&,
                                                        const std::vector<double>&);

}  // namespace frostwall::sph
