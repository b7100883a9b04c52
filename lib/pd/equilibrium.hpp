// The equilibrium of the linear PD solid (linear kinematics) by a direct
// sparse solve instead of dynamic relaxation. With linear kinematics the
// forces are linear in u, F(u) = f_T + sum k3 (xi . (u_k - u_i)) xi, and
// V_i F_i is minus the gradient of a quadratic energy (V_i w_ij = V_j w_ji),
// so the equilibrium solves K z = r with K symmetric positive
// (semi-)definite. The unknowns z are the particles the relaxation moves
// (one per axis), one per axis for each rigid group (a frozen pore riding
// on the plate), and nothing for held particles; a roller image follows
// its particle through its reflection.
//
// K is factored (sparse Cholesky, fill-reducing ordering) and the factor
// is kept: while bonds break and pores start to freeze, each solve is
// conjugate gradients on the current K, preconditioned by the factor of
// an earlier K. A few broken bonds leave the factor an excellent
// preconditioner; when CG needs more than `refactor_after` iterations the
// next solve factors again. A dynamic relaxation needs ~sqrt(n) sweeps per
// equilibrium (2 750 at 90 000 particles); this needs one back
// substitution per CG iteration, and usually one to a few.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "pd/relaxation.hpp"
#include "pd/solid.hpp"

namespace frostwall::pd {

class DirectEquilibrium {
 public:
  // tolerance: CG stops when the residual force is below this times the
  // load's (the force the held and thermal loads put on unmoved particles).
  explicit DirectEquilibrium(double tolerance = 1e-8, int refactor_after = 25, int max_iterations = 400,
                             double patch_reach = 5.0);
  ~DirectEquilibrium();
  DirectEquilibrium(DirectEquilibrium&&) noexcept;
  DirectEquilibrium& operator=(DirectEquilibrium&&) noexcept;

  // Brings u to the equilibrium at dT (held particles keep theirs; rigid
  // groups translate). iterations: CG iterations.
  RelaxationResult solve(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT);
  // The same while the solid changes (bonds that break): solve, then
  // adjust() at that equilibrium; again until adjust() changes nothing.
  // A cascade of breaking bonds (a crack running at a fixed load) moves
  // the solid only near the bonds that broke: after each break the
  // neighbourhood of the broken bonds (within `patch_reach` horizons, the
  // rest held) is brought to equilibrium by its own small direct solve,
  // until nothing more breaks there; then the whole solid again, and the
  // equilibrium returned is one where nothing breaks. A break that touches
  // more than a quarter of the particles goes straight to the whole.
  RelaxationResult solve_adjusting(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT,
                                   const std::function<bool()>& adjust);
  int factorizations() const { return factorizations_; }
  long patch_solves() const { return patch_solves_; }
  long solves() const { return solves_; }  // equilibria found (each break round is one)

 private:
  struct Factor;
  void factor(const PdSolid& solid);
  // The equilibrium of the particles near `seeds` with the rest held;
  // false (nothing done) when that neighbourhood is too large.
  bool solve_near(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT,
                  const std::vector<std::uint32_t>& seeds);
  struct Patch;
  std::unique_ptr<Patch> patch_;
  long patch_solves_ = 0;
  double tolerance_;
  static constexpr double anchor_ = 1e-12;
  int refactor_after_, max_iterations_, factorizations_ = 0;
  double patch_reach_;  // horizons
  long solves_ = 0;
  bool stale_ = true;
  std::unique_ptr<Factor> factor_;
};

}  // namespace frostwall::pd
