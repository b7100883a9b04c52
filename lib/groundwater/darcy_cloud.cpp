#include "groundwater/darcy_cloud.hpp"

#include <Eigen/CholmodSupport>

#include "particles/parallel.hpp"
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>

namespace frostwall::groundwater {

// Small clouds: Eigen's simplicial LDL^T. Large ones (the shaft's half
// section): CHOLMOD's supernodal LL^T, whose dense blocks make it an order
// faster there (the simplicial factor was 79 % of a full-size run's time),
// while on small clouds its BLAS calls cost more than they save (each
// wakes the OpenMP threads: 60 s against 13 s for 411 solves of 8 000
// unknowns on 2 threads).
constexpr std::size_t supernodal_from = 40000;

struct DarcyCloud::Factor {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  bool analysed = false, supernodal = false;

  bool factor(const Eigen::SparseMatrix<double>& A) {
    if (!analysed) {
      supernodal = std::size_t(A.rows()) >= supernodal_from;
      if (supernodal) llt.analyzePattern(A);
      else ldlt.analyzePattern(A);
      analysed = true;
    }
    if (supernodal) {
      llt.factorize(A);
      return llt.info() == Eigen::Success;
    }
    ldlt.factorize(A);
    return ldlt.info() == Eigen::Success;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    return supernodal ? Eigen::VectorXd(llt.solve(b)) : Eigen::VectorXd(ldlt.solve(b));
  }
};

DarcyCloud::DarcyCloud(const particles::PairWeights& pairs, std::vector<double> volume,
                       std::vector<double> fixed_potential)
    : pairs_(pairs),
      volume_(std::move(volume)),
      fixed_(std::move(fixed_potential)),
      factor_(std::make_unique<Factor>()) {
  if (volume_.size() < pairs_.n_free || pairs_.n_free + fixed_.size() < volume_.size())
    throw std::invalid_argument("DarcyCloud: volumes and fixed potentials do not cover the particles");
}

DarcyCloud::~DarcyCloud() = default;

namespace {

// 4 k_i k_j / (k_i + k_j): 2k for equal k, the factor the SPH weights G_ij
// expect (sum_j G_ij (x_j - x_i)(x_j - x_i)^T = I), as for conduction.
double pair_permeability(double a, double b) { return a + b > 0.0 ? 4.0 * a * b / (a + b) : 0.0; }

}  // namespace

DarcySolveReport DarcyCloud::solve(const std::vector<double>& k) {
  const std::size_t n = pairs_.n_free;
  auto fixed_value = [&](std::size_t j) { return fixed_[j - n]; };
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(pairs_.pairs() + n);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    double diagonal = 0.0;
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e) {
      const std::size_t j = pairs_.column[e];
      if (j == i) continue;                                // a particle's own mirror image carries nothing
      if (j >= n && std::isnan(fixed_value(j))) continue;  // no flow through a pipe
      const double a = volume_[i] * pairs_.weight[e] * pair_permeability(k[i], k[j]);
      diagonal += a;
      if (j < n) entries.emplace_back(int(i), int(j), -a);
      else rhs[Eigen::Index(i)] += a * fixed_value(j);
    }
    // A particle cut off from every neighbour keeps its potential at 0
    // (never the case on a connected cloud).
    entries.emplace_back(int(i), int(i), diagonal > 0.0 ? diagonal : 1.0);
  }
  Eigen::SparseMatrix<double> A(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  A.setFromTriplets(entries.begin(), entries.end());
  DarcySolveReport report;
  // CHOLMOD's BLAS calls on one thread: the supernodes of a 2-D cloud are
  // small, and a team forked for each cost 2.4 times the whole run's time
  // under seepage (bench/README.md).
  report.factored = particles::serially([&] { return factor_->factor(A); });
  if (!report.factored)
    throw std::runtime_error("Darcy flow: the system could not be factored (is the cloud connected?)");
  const Eigen::VectorXd x = particles::serially([&] { return factor_->solve(rhs); });
  psi_.assign(volume_.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i) psi_[i] = x[Eigen::Index(i)];
  for (std::size_t j = n; j < psi_.size(); ++j) psi_[j] = fixed_value(j);
  // The pair fluxes and how well each free particle balances.
  flux_.assign(pairs_.pairs(), 0.0);
  double largest = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    double net = 0.0;
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e) {
      const std::size_t j = pairs_.column[e];
      if (j == i || std::isnan(psi_[j])) continue;
      flux_[e] = volume_[i] * pairs_.weight[e] * pair_permeability(k[i], k[j]) * (psi_[i] - psi_[j]);
      net += flux_[e];
      largest = std::max(largest, std::abs(flux_[e]));
    }
    worst = std::max(worst, std::abs(net));
  }
  report.largest_imbalance = largest > 0.0 ? worst / largest : 0.0;
  return report;
}

double DarcyCloud::inflow_from_boundary(bool gross) const {
  double in = 0.0;
  for (std::size_t i = 0; i < pairs_.n_free; ++i)
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e)
      if (pairs_.column[e] >= pairs_.n_free && (!gross || flux_[e] < 0.0)) in -= flux_[e];
  return in;
}

}  // namespace frostwall::groundwater
