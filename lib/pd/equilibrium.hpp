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

#include <functional>
#include <memory>
#include <vector>

#include "pd/relaxation.hpp"
#include "pd/solid.hpp"

namespace frostwall::pd {

class DirectEquilibrium {
 public:
  // tolerance: CG stops when the RMS of the error estimate M^-1 r (M the
  // factored K) is below this times the RMS displacement of the unknowns.
  // refactor_after: CG iterations after which the next solve factors K
  // again; 0: factor K whenever it changed, so every solve is direct.
  // 20 was the fastest of 0, 5, 10, 15, 20, 30 and 60 on the mortar plate
  // at 3 um to 0.02 s (120 s against 259 s at 60 and 566 s at 0, 2
  // threads; bench/README.md): a cascade's rounds need ever more CG
  // iterations on an old factor, and a factorization costs about as much
  // as twenty of them.
  explicit DirectEquilibrium(double tolerance = 1e-8, int refactor_after = 20, int max_iterations = 400);
  ~DirectEquilibrium();
  DirectEquilibrium(DirectEquilibrium&&) noexcept;
  DirectEquilibrium& operator=(DirectEquilibrium&&) noexcept;

  // Brings u to the equilibrium at dT (held particles keep theirs; rigid
  // groups translate). iterations: CG iterations.
  RelaxationResult solve(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT);
  // The same while the solid changes (bonds that break): solve, then
  // adjust() at that equilibrium; again until adjust() changes nothing.
  // Every round is a whole-solid equilibrium: re-solving only a patch
  // round the broken bonds (the rest held) was tried and changed the
  // crack pattern (a fifth to a third fewer broken bonds on the mortar
  // plate at 2 um: a held patch is too stiff), and was no faster.
  RelaxationResult solve_adjusting(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT,
                                   const std::function<bool()>& adjust);
  int factorizations() const { return factorizations_; }
  long solves() const { return solves_; }  // equilibria found (each break round is one)

 private:
  struct Factor;
  void factor(const PdSolid& solid);
  double tolerance_;
  static constexpr double anchor_ = 1e-12;
  int refactor_after_, max_iterations_, factorizations_ = 0;
  long solves_ = 0;
  bool stale_ = true;
  std::unique_ptr<Factor> factor_;
};

}  // namespace frostwall::pd
