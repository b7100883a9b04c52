#include "sph/moment_correction.hpp"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sph/two_level_solver.hpp"

namespace frostwall::sph {

using particles::Vec;

namespace {

template <int Dim>
constexpr int unknowns = MomentSystem<Dim>::unknowns;

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

// The other end's features: its vector to us is -u with u = A^T d (A the
// image's mirror map), |u| = |d|.
template <int Dim>
Features<Dim> far_features_of(const Vec<Dim>& d, const Eigen::Matrix<double, Dim, Dim>& to_image, double l) {
  Features<Dim> f = features<Dim>(to_image.transpose() * d, l);
  f.template head<Dim>() *= -1.0;
  return f;
}

// Fields of multipliers the system nearly ignores, per particle, in the
// scaled unknowns (l lambda, l^2 mu): a pair changes by
// (lambda_i - lambda_j) . d + (mu_i + mu_j) |d|^2, which is zero for a
// common shift of lambda, for lambda rotating with position, and for the
// dilation lambda = x, mu = 1/2, wherever a particle's neighbours are all
// free. Only fixed neighbours and mirror planes pin them, so these are
// the slow modes of plain CG; they span the solver's coarse space, with
// a common mu. (They are the linear members of a larger family: any
// lambda whose symmetric gradient is 2 mu I, a conformal field in 2-D, is
// nearly ignored too; adding the quadratic ones gained little: 38 -> 33
// iterations on the single ring. A full ring of measured pipes with no
// symmetry, 16 000 particles at 0.1 m, takes 49 iterations; the same
// ring unfolded from the wedge (numerics.symmetry "off") took 280, about
// 4 s, where incomplete-Cholesky CG took 195 and 5.5 s with its
// factorisation: the unfolding leaves 52 pairs of nearly coincident
// particles at the axis, the likely cause.)
template <int Dim>
Eigen::Matrix<double, unknowns<Dim>, MomentSystem<Dim>::modes> near_null_modes(const Vec<Dim>& x, double l) {
  Eigen::Matrix<double, unknowns<Dim>, MomentSystem<Dim>::modes> m =
      Eigen::Matrix<double, unknowns<Dim>, MomentSystem<Dim>::modes>::Zero();
  int c = 0;
  for (int d = 0; d < Dim; ++d) m(d, c++) = l;  // shifts
  for (int a = 0; a < Dim; ++a)
    for (int b = a + 1; b < Dim; ++b, ++c) {  // rotations
      m(a, c) = -l * x[b];
      m(b, c) = l * x[a];
    }
  m.col(c).template head<Dim>() = l * x;  // dilation
  m(Dim, c++) = 0.5 * l * l;
  m(Dim, c) = l * l;  // a common mu
  return m;
}

}  // namespace

template <int Dim>
MomentSystem<Dim> moment_system(const LaplacianPairs& pairs, const std::vector<Vec<Dim>>& position,
                                const std::vector<double>& volume, const std::vector<Vec<Dim>>& pair_vector,
                                const std::vector<Eigen::Matrix<double, Dim, Dim>>& to_image,
                                const std::vector<double>& length_scale) {
  constexpr int P = unknowns<Dim>;
  const std::size_t n = pairs.n_free;

  // Which particles get their moments set: those whose neighbours surround
  // them (first moment well below the first absolute moment).
  MomentSystem<Dim> system;
  std::vector<long>& slot = system.slot;
  slot.assign(n, -1);
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
  if (rows == 0) return system;

  auto far_features = [&](std::size_t e, std::uint32_t j) {
    return far_features_of<Dim>(pair_vector[e], to_image[e], length_scale[j]);
  };

  // dW_e = W_e^2 (psi_i . z_i + psi_j . z_j): least squares of the relative
  // changes dW/W (a pair's weight moves in proportion to its size, so the
  // small weights at the rim of the kernel keep their sign). Row i:
  // sum_e phi_e (W_e + dW_e) = target_i. One block row per particle, its
  // own block first; a neighbour met twice (itself and an image) adds up.
  using Block = typename BlockMatrix<P>::Block;
  BlockMatrix<P>& K = system.K;
  K.row_start.assign(rows + 1, 0);
  Eigen::VectorXd& rhs = system.rhs;
  rhs = Eigen::VectorXd::Zero(rows * P);
  auto& modes = system.near_null;
  modes.resize(rows);
  std::vector<std::pair<std::uint32_t, Block>> row;
  for (std::size_t i = 0; i < n; ++i) {
    if (slot[i] < 0) continue;
    const auto r = static_cast<std::uint32_t>(slot[i]);
    const double l = length_scale[i];
    row.assign(1, {r, Block::Zero()});
    Features<Dim> moment = Features<Dim>::Zero();
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      const double W = volume[i] * pairs.weight[e];
      const Features<Dim> phi = features<Dim>(pair_vector[e], l);
      moment += W * phi;
      row.front().second += W * W * phi * phi.transpose();
      const std::uint32_t j = pairs.column[e];
      if (j >= n || slot[j] < 0) continue;
      const auto c = static_cast<std::uint32_t>(slot[j]);
      const Block part = W * W * phi * far_features(e, j).transpose();
      auto it = std::find_if(row.begin(), row.end(), [&](const auto& b) { return b.first == c; });
      if (it == row.end()) row.emplace_back(c, part);
      else it->second += part;
    }
    for (const auto& [c, block] : row) {
      K.column.push_back(c);
      K.block.push_back(block);
    }
    K.row_start[r + 1] = K.column.size();
    Features<Dim> target = Features<Dim>::Zero();
    target[Dim] = Dim * volume[i] / (l * l);
    rhs.template segment<P>(r * P) = target - moment;
    modes[r] = near_null_modes<Dim>(position[i], l);
  }
  // A whisker of regularisation: without fixed particles a common shift of
  // all lambda changes no pair between free particles.
  double largest = 0.0;
  for (std::size_t r = 0; r < K.rows(); ++r) largest = std::max(largest, K.block[K.row_start[r]].diagonal().maxCoeff());
  for (std::size_t r = 0; r < K.rows(); ++r) K.block[K.row_start[r]].diagonal().array() += 1e-12 * largest;
  return system;
}

// K is symmetric positive definite. Conjugate gradients with the two-level
// preconditioner take about 40 iterations to 1e-8 on a graded shaft wedge
// (20 000 unknowns); incomplete Cholesky took 100 and twice the time, a
// sparse LDLT (the fallback) three times.
template <int Dim>
Eigen::VectorXd solve_moment_system(const MomentSystem<Dim>& system, TwoLevelReport* report) {
  const auto& K = system.K;
  const Eigen::VectorXd& rhs = system.rhs;
  Eigen::VectorXd z;
  if (solve_two_level(K, rhs, system.near_null, 1e-8, 500, z, report)) return z;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(K.sparse());
  if (solver.info() != Eigen::Success) throw std::runtime_error("moment correction: the moment system is singular");
  return solver.solve(rhs);
}

template <int Dim>
MomentCorrectionReport correct_pair_moments(LaplacianPairs& pairs, const std::vector<Vec<Dim>>& position,
                                            const std::vector<double>& volume, const std::vector<Vec<Dim>>& pair_vector,
                                            const std::vector<Eigen::Matrix<double, Dim, Dim>>& to_image,
                                            const std::vector<double>& length_scale) {
  constexpr int P = unknowns<Dim>;
  const std::size_t n = pairs.n_free;
  MomentCorrectionReport report;
  const MomentSystem<Dim> system = moment_system<Dim>(pairs, position, volume, pair_vector, to_image, length_scale);
  const std::vector<long>& slot = system.slot;
  report.corrected = system.K.rows();
  if (report.corrected == 0) return report;
  const Eigen::VectorXd z = solve_moment_system<Dim>(system);
  auto far_features = [&](std::size_t e, std::uint32_t j) {
    return far_features_of<Dim>(pair_vector[e], to_image[e], length_scale[j]);
  };

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

template MomentSystem<2> moment_system<2>(const LaplacianPairs&, const std::vector<Vec<2>>&, const std::vector<double>&,
                                          const std::vector<Vec<2>>&, const std::vector<Eigen::Matrix<double, 2, 2>>&,
                                          const std::vector<double>&);
template Eigen::VectorXd solve_moment_system<2>(const MomentSystem<2>&, TwoLevelReport*);
template MomentCorrectionReport correct_pair_moments<2>(LaplacianPairs&, const std::vector<Vec<2>>&,
                                                        const std::vector<double>&, const std::vector<Vec<2>>&,
                                                        const std::vector<Eigen::Matrix<double, 2, 2>>&,
                                                        const std::vector<double>&);

}  // namespace frostwall::sph
