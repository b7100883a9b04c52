// Conjugate gradients for a symmetric positive definite matrix of small
// dense blocks (one block row per particle), preconditioned by a two-level
// cycle: block-Jacobi smoothing for the particle-scale error, and an exact
// solve on a coarse space for the smooth error that smoothing barely
// touches. The coarse space is spanned, on aggregates of neighbouring
// particles, by the caller's near-null vectors: the fields the matrix
// nearly ignores (for the moment-correction system, shifts, rotations and
// a dilation of the multipliers, moment_correction.cpp). With those the
// iteration count no longer grows with the number of particles across the
// domain, which is what made plain or incomplete-Cholesky CG slow there.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <Eigen/StdVector>
#include <cstdint>
#include <vector>

namespace frostwall::sph {

template <int B>
struct BlockMatrix {
  using Block = Eigen::Matrix<double, B, B>;
  // Block row r holds blocks e in [row_start[r], row_start[r + 1]), at
  // block column column[e]; each column at most once per row.
  std::vector<std::size_t> row_start{0};
  std::vector<std::uint32_t> column;
  std::vector<Block, Eigen::aligned_allocator<Block>> block;

  std::size_t rows() const { return row_start.size() - 1; }
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;  // y = K x
  Eigen::SparseMatrix<double> sparse() const;                         // the same matrix, scalar entries
};

struct TwoLevelReport {
  int iterations = 0;
  double relative_residual = 0.0;
  std::size_t aggregates = 0;
  bool converged = false;
};

// Solves K z = b to |b - K z| <= tolerance |b|. near_null[r] (B x M) is the
// near-null basis restricted to block row r. Returns false (z unusable) if
// the iteration did not converge within max_iterations or broke down.
template <int B, int M>
bool solve_two_level(const BlockMatrix<B>& K, const Eigen::VectorXd& b,
                     const std::vector<Eigen::Matrix<double, B, M>>& near_null, double tolerance, int max_iterations,
                     Eigen::VectorXd& z, TwoLevelReport* report = nullptr);

}  // namespace frostwall::sph
