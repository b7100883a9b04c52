#include "sph/two_level_solver.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>

#include "particles/parallel.hpp"

namespace frostwall::sph {

using particles::for_each_particle;

template <int B>
void BlockMatrix<B>::multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.resize(x.size());
  for_each_particle(rows(), [&](std::size_t r) {
    Eigen::Matrix<double, B, 1> sum = Eigen::Matrix<double, B, 1>::Zero();
    for (std::size_t e = row_start[r]; e < row_start[r + 1]; ++e)
      sum += block[e] * x.template segment<B>(B * column[e]);
    y.template segment<B>(B * r) = sum;
  });
}

template <int B>
Eigen::SparseMatrix<double> BlockMatrix<B>::sparse() const {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(block.size() * B * B);
  for (std::size_t r = 0; r < rows(); ++r)
    for (std::size_t e = row_start[r]; e < row_start[r + 1]; ++e)
      for (int a = 0; a < B; ++a)
        for (int b = 0; b < B; ++b) triplets.emplace_back(B * r + a, B * column[e] + b, block[e](a, b));
  Eigen::SparseMatrix<double> A(B * rows(), B * rows());
  A.setFromTriplets(triplets.begin(), triplets.end());
  return A;
}

namespace {

// Greedy aggregation on the block graph: a row whose neighbours are all
// free founds an aggregate with them; the rest join a neighbouring
// aggregate, and what is still alone groups with its free neighbours.
template <int B>
std::vector<std::uint32_t> aggregate(const BlockMatrix<B>& K, std::size_t& count) {
  constexpr std::uint32_t none = ~0u;
  const std::size_t n = K.rows();
  std::vector<std::uint32_t> agg(n, none);
  count = 0;
  auto found = [&](std::size_t r, bool only_if_all_free) {
    if (only_if_all_free)
      for (std::size_t e = K.row_start[r]; e < K.row_start[r + 1]; ++e)
        if (agg[K.column[e]] != none) return;
    for (std::size_t e = K.row_start[r]; e < K.row_start[r + 1]; ++e)
      if (agg[K.column[e]] == none) agg[K.column[e]] = static_cast<std::uint32_t>(count);
    agg[r] = static_cast<std::uint32_t>(count++);
  };
  for (std::size_t r = 0; r < n; ++r)
    if (agg[r] == none) found(r, true);
  for (std::size_t r = 0; r < n; ++r)
    if (agg[r] == none)
      for (std::size_t e = K.row_start[r]; e < K.row_start[r + 1] && agg[r] == none; ++e)
        if (agg[K.column[e]] != none) agg[r] = agg[K.column[e]];
  for (std::size_t r = 0; r < n; ++r)
    if (agg[r] == none) found(r, false);
  return agg;
}

template <int B, int M>
class TwoLevelCycle {
 public:
  using Basis = Eigen::Matrix<double, B, M>;

  TwoLevelCycle(const BlockMatrix<B>& K, const std::vector<Basis>& near_null) : K_(K) {
    const std::size_t n = K.rows();
    // Block-Jacobi: the inverse of each diagonal block.
    D_inverse_.resize(n);
    ok_ = true;
    for (std::size_t r = 0; r < n; ++r) {
      bool found = false;
      for (std::size_t e = K.row_start[r]; e < K.row_start[r + 1]; ++e)
        if (K.column[e] == r) {
          Eigen::FullPivLU<Eigen::Matrix<double, B, B>> lu(K.block[e]);
          if (!lu.isInvertible()) break;
          D_inverse_[r] = lu.inverse();
          found = true;
        }
      ok_ = ok_ && found;
    }
    if (!ok_) return;

    // Coarse basis: per aggregate, an orthonormal basis of the near-null
    // vectors restricted to it (columns beyond their rank left zero).
    aggregate_ = aggregate(K, aggregates_);
    std::vector<std::vector<std::uint32_t>> members(aggregates_);
    for (std::size_t r = 0; r < n; ++r) members[aggregate_[r]].push_back(static_cast<std::uint32_t>(r));
    basis_.assign(n, Basis::Zero());
    std::vector<int> rank(aggregates_);
    for (std::size_t a = 0; a < aggregates_; ++a) {
      const auto& m = members[a];
      Eigen::MatrixXd stacked(B * m.size(), M);
      for (std::size_t k = 0; k < m.size(); ++k) stacked.middleRows(B * k, B) = near_null[m[k]];
      Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(stacked);
      qr.setThreshold(1e-10);
      rank[a] = static_cast<int>(qr.rank());
      const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(stacked.rows(), M);
      for (std::size_t k = 0; k < m.size(); ++k) basis_[m[k]].leftCols(rank[a]) = Q.block(B * k, 0, B, rank[a]);
    }

    // Coarse matrix P^T K P, block (a, c) = sum over i in a, j in c of
    // Q_i^T K_ij Q_j; a dead coarse unknown (beyond an aggregate's rank)
    // gets a one on its diagonal.
    using Small = Eigen::Matrix<double, M, M>;
    std::vector<Eigen::Triplet<double>> triplets;
    std::vector<std::pair<std::uint32_t, Small>> row;
    for (std::size_t a = 0; a < aggregates_; ++a) {
      row.clear();
      for (std::uint32_t i : members[a])
        for (std::size_t e = K.row_start[i]; e < K.row_start[i + 1]; ++e) {
          const std::uint32_t j = K.column[e];
          const std::uint32_t c = aggregate_[j];
          const Small part = basis_[i].transpose() * K.block[e] * basis_[j];
          auto it = std::find_if(row.begin(), row.end(), [&](const auto& p) { return p.first == c; });
          if (it == row.end()) row.emplace_back(c, part);
          else it->second += part;
        }
      for (const auto& [c, small] : row)
        for (int p = 0; p < M; ++p)
          for (int q = 0; q < M; ++q)
            if (small(p, q) != 0.0) triplets.emplace_back(M * a + p, M * c + q, small(p, q));
      for (int p = rank[a]; p < M; ++p) triplets.emplace_back(M * a + p, M * a + p, 1.0);
    }
    Eigen::SparseMatrix<double> coarse(M * aggregates_, M * aggregates_);
    coarse.setFromTriplets(triplets.begin(), triplets.end());
    coarse_.compute(coarse);
    ok_ = coarse_.info() == Eigen::Success;
  }

  bool ok() const { return ok_; }
  std::size_t aggregates() const { return aggregates_; }

  // x = (cycle) r: smooth, coarse correction, smooth. The same smoother
  // before and after keeps the cycle symmetric, as CG needs.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& x) {
    x.setZero(r.size());
    smooth(r, x);
    K_.multiply(x, Kx_);
    residual_ = r - Kx_;
    Eigen::VectorXd rc = Eigen::VectorXd::Zero(M * aggregates_);
    for (std::size_t i = 0; i < aggregate_.size(); ++i)
      rc.template segment<M>(M * aggregate_[i]) += basis_[i].transpose() * residual_.template segment<B>(B * i);
    const Eigen::VectorXd ec = coarse_.solve(rc);
    for_each_particle(aggregate_.size(), [&](std::size_t i) {
      x.template segment<B>(B * i) += basis_[i] * ec.template segment<M>(M * aggregate_[i]);
    });
    K_.multiply(x, Kx_);
    residual_ = r - Kx_;
    smooth(residual_, x);
  }

 private:
  // Damped block Jacobi. The cycle stays positive definite (as CG needs)
  // while 0.7 times the largest eigenvalue of D^-1 K is below 2; that
  // eigenvalue measured 2.0 on the single ring's moment system, and a
  // divergence would end in the caller's fallback.
  void smooth(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
    constexpr double omega = 0.7;
    for_each_particle(D_inverse_.size(), [&](std::size_t i) {
      x.template segment<B>(B * i) += omega * (D_inverse_[i] * r.template segment<B>(B * i));
    });
  }

  const BlockMatrix<B>& K_;
  std::vector<Eigen::Matrix<double, B, B>, Eigen::aligned_allocator<Eigen::Matrix<double, B, B>>> D_inverse_;
  std::vector<std::uint32_t> aggregate_;
  std::size_t aggregates_ = 0;
  std::vector<Basis, Eigen::aligned_allocator<Basis>> basis_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> coarse_;
  Eigen::VectorXd Kx_, residual_;
  bool ok_ = false;
};

}  // namespace

template <int B, int M>
bool solve_two_level(const BlockMatrix<B>& K, const Eigen::VectorXd& b,
                     const std::vector<Eigen::Matrix<double, B, M>>& near_null, double tolerance, int max_iterations,
                     Eigen::VectorXd& z, TwoLevelReport* report) {
  TwoLevelReport local;
  TwoLevelReport& rep = report ? *report : local;
  rep = TwoLevelReport{};
  TwoLevelCycle<B, M> cycle(K, near_null);
  if (!cycle.ok()) return false;
  rep.aggregates = cycle.aggregates();
  z = Eigen::VectorXd::Zero(b.size());
  const double b_norm = b.norm();
  if (b_norm == 0.0) return rep.converged = true;
  Eigen::VectorXd r = b, s, p, Kp;
  cycle.apply(r, s);
  p = s;
  double rs = r.dot(s);
  for (int it = 1; it <= max_iterations; ++it) {
    K.multiply(p, Kp);
    const double pKp = p.dot(Kp);
    if (!(pKp > 0.0) || !(rs > 0.0)) return false;  // lost positive definiteness
    const double alpha = rs / pKp;
    z += alpha * p;
    r -= alpha * Kp;
    rep.iterations = it;
    rep.relative_residual = r.norm() / b_norm;
    if (rep.relative_residual <= tolerance) return rep.converged = true;
    if (!(rep.relative_residual < 1e3)) return false;  // diverging: no use going on
    cycle.apply(r, s);
    const double rs_next = r.dot(s);
    p = s + (rs_next / rs) * p;
    rs = rs_next;
  }
  return false;
}

template struct BlockMatrix<3>;
template bool solve_two_level<3, 5>(const BlockMatrix<3>&, const Eigen::VectorXd&,
                                    const std::vector<Eigen::Matrix<double, 3, 5>>&, double, int, Eigen::VectorXd&,
                                    TwoLevelReport*);

}  // namespace frostwall::sph
