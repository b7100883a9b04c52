#include "pd/equilibrium.hpp"

#include <Eigen/CholmodSupport>
#include <cmath>

#include "particles/parallel.hpp"

namespace frostwall::pd {

struct DirectEquilibrium::Factor {
  // The unknown of each free particle's axis (2 per particle), -1 for held
  // particles outside groups: the map P from unknowns to displacements.
  std::vector<long> dof;
  std::size_t unknowns = 0, held = 0, groups = 0;
  Eigen::VectorXd anchor;     // the spring each unknown has to where it was
  bool analysed = false;      // the pattern's ordering and symbolic factor done
  std::uint64_t version = 0;  // the solid's stiffness version it factors
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> cholesky;

  void map(const PdSolid& solid) {
    const std::size_t n = solid.size();
    dof.assign(2 * n, -1);
    long m = 0;
    held = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (solid.held(i)) {
        ++held;
        continue;
      }
      dof[2 * i] = m++;
      dof[2 * i + 1] = m++;
    }
    groups = solid.groups().size();
    for (const auto& group : solid.groups()) {
      for (std::size_t i : group) {
        dof[2 * i] = m;
        dof[2 * i + 1] = m + 1;
      }
      m += 2;
    }
    unknowns = static_cast<std::size_t>(m);
  }
  bool matches(const PdSolid& solid) const {
    if (dof.size() != 2 * solid.size() || groups != solid.groups().size()) return false;
    std::size_t h = 0;
    for (std::size_t i = 0; i < solid.size(); ++i) h += solid.held(i);
    return h == held;
  }
  // P^T (V f): the force on each unknown.
  void gather(const PdSolid& solid, const std::vector<double>& f, Eigen::VectorXd& out) const {
    out.setZero(static_cast<Eigen::Index>(unknowns));
    const auto& V = solid.volume();
    for (std::size_t k = 0; k < dof.size(); ++k)
      if (dof[k] >= 0) out[dof[k]] += V[k / 2] * f[k];
  }
  // u (2 per particle) = P z.
  void scatter(const Eigen::VectorXd& z, std::vector<double>& u) const {
    u.resize(dof.size());
    particles::for_each_particle(dof.size(), [&](std::size_t k) { u[k] = dof[k] >= 0 ? z[dof[k]] : 0.0; });
  }
};

DirectEquilibrium::DirectEquilibrium(double tolerance, int refactor_after, int max_iterations)
    : tolerance_(tolerance), refactor_after_(refactor_after), max_iterations_(max_iterations) {}
DirectEquilibrium::~DirectEquilibrium() = default;
DirectEquilibrium::DirectEquilibrium(DirectEquilibrium&&) noexcept = default;
DirectEquilibrium& DirectEquilibrium::operator=(DirectEquilibrium&&) noexcept = default;

void DirectEquilibrium::factor(const PdSolid& solid) {
  if (!factor_) factor_ = std::make_unique<Factor>();
  Factor& F = *factor_;
  if (!F.matches(solid)) {
    F.map(solid);
    F.analysed = false;
  }
  // Each bond's row block V_i k3 xi xi^T against i's own unknowns and,
  // through the far end's map A, against j's: the lower triangle only.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * solid.bonds());
  const auto& V = solid.volume();
  std::vector<double> diagonal(F.unknowns, 0.0);
  solid.for_each_spring([&](std::size_t i, long j, const Eigen::Matrix2d& A, double k3, const Vec2& xi) {
    const Eigen::Matrix2d B = V[i] * k3 * xi * xi.transpose();
    const Eigen::Matrix2d BA = B * A;
    for (int a = 0; a < 2; ++a) {
      const long r = F.dof[2 * i + a];
      if (r < 0) continue;
      for (int b = 0; b < 2; ++b) {
        const long c = F.dof[2 * i + b];
        if (c >= 0 && c <= r) entries.emplace_back(r, c, B(a, b));
        const long cj = j >= 0 ? F.dof[2 * j + b] : -1;
        if (cj >= 0 && cj <= r) entries.emplace_back(r, cj, -BA(a, b));
      }
      diagonal[r] += B(a, a);
    }
  });
  // Floating fragments (material cut loose by cracks) and unknowns
  // without stiffness (liquid water, a pore not yet frozen) make K
  // singular. Every unknown gets a spring of `anchor` times its diagonal
  // to where it was (the same in the operator CG solves): a fragment stays
  // put instead of drifting with rounding, and a connected body's
  // equilibrium moves by ~anchor x (L / dx)^2 relative, 1e-7 at
  // 300 spacings across. Unknowns without stiffness get a unit diagonal.
  F.anchor.resize(F.unknowns);
  for (std::size_t r = 0; r < F.unknowns; ++r) {
    F.anchor[r] = diagonal[r] > 0.0 ? anchor_ * diagonal[r] : 1.0;
    entries.emplace_back(r, r, F.anchor[r]);
  }
  const auto m = static_cast<Eigen::Index>(F.unknowns);
  Eigen::SparseMatrix<double> K(m, m);
  K.setFromTriplets(entries.begin(), entries.end());
  entries = {};
  // Every bond is in the pattern, broken or not, so the ordering and the
  // symbolic factor (half the work) are done once per map of unknowns.
  if (!F.analysed) {
    F.cholesky.analyzePattern(K);
    F.analysed = true;
  }
  // OpenBLAS's threads cost more than they save on a small factor (a
  // 2 400-particle plate's 319 factors: 23 s on one thread, 93 s on two);
  // the paper's 169 000 unknowns factor in 9 s on two (bench/README.md).
  if (F.unknowns < 20000) particles::serially([&] { F.cholesky.factorize(K); });
  else F.cholesky.factorize(K);
  F.version = solid.stiffness_version();
  ++factorizations_;
  stale_ = false;
}

RelaxationResult DirectEquilibrium::solve(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT) {
  RelaxationResult result;
  ++solves_;
  // refactor_after 0: K's own factor for every solve (the reference the
  // preconditioned solves are checked against).
  const bool changed = factor_ && factor_->version != solid.stiffness_version();
  if (stale_ || !factor_ || !factor_->matches(solid) || (refactor_after_ == 0 && changed)) factor(solid);
  const Factor& F = *factor_;
  std::vector<double> dT_all, thermal, zero(2 * solid.size(), 0.0), u_all, force, up;
  solid.extend_temperature(dT, dT_all);
  solid.thermal_force(dT_all, thermal);
  // The residual force on the unknowns at u, and K p.
  Eigen::VectorXd r, z, p, Kp;
  solid.extend(u, u_all);
  solid.forces_linear(u_all, thermal, force);
  F.gather(solid, force, r);
  auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    F.scatter(x, up);
    solid.extend_homogeneous(up, u_all);
    solid.forces_linear(u_all, zero, force);
    F.gather(solid, force, out);
    out = F.anchor.cwiseProduct(x) - out;
  };
  // RMS of u + P x over the displacements the unknowns move.
  std::size_t moved = 0;
  for (long d : F.dof) moved += d >= 0;
  auto rms_displacement = [&](const Eigen::VectorXd& x) {
    double s = 0.0;
    for (std::size_t k = 0; k < F.dof.size(); ++k)
      if (F.dof[k] >= 0) s += (u[k] + x[F.dof[k]]) * (u[k] + x[F.dof[k]]);
    return moved ? std::sqrt(s / moved) : 0.0;
  };
  if (F.unknowns == 0 || r.norm() == 0.0) {
    result.converged = true;
    return result;
  }
  // One back substitution with the kept factor (on one thread: many
  // small BLAS-2 calls).
  auto precondition = [&](const Eigen::VectorXd& v) {
    return particles::serially([&] { return Eigen::VectorXd(F.cholesky.solve(v)); });
  };
  z = precondition(r);
  Eigen::VectorXd x;
  // The factor is K's own (nothing changed since): z is the answer, to
  // rounding; a CG step would only confirm it at the cost of a second
  // back substitution.
  const bool exact = F.version == solid.stiffness_version();
  if (exact) {
    x = z;
    result.iterations = 1;
    result.converged = true;
  } else {
    p = z;
    double rz = r.dot(z);
    x = Eigen::VectorXd::Zero(r.size());
    for (int it = 0; it < max_iterations_; ++it) {
      apply(p, Kp);
      const double pKp = p.dot(Kp);
      if (!(pKp > 0.0)) break;
      const double alpha = rz / pKp;
      x += alpha * p;
      r -= alpha * Kp;
      result.iterations = it + 1;
      // The test is on z = M^-1 r, the error left as the factor sees it,
      // not on the step just taken: after bonds break, a step of CG
      // preconditioned by the factor of the unbroken K can be small while
      // the crack tip is still far from equilibrium, and a cascade judged
      // on it stops early (a 120 x 80 um plate with two pores at 2 um:
      // 5 768 bonds broken against 6 632 with K's own factor every round;
      // this test: 6 630).
      z = precondition(r);
      const double du = z.norm() / std::sqrt(double(z.size())), uu = rms_displacement(x);
      result.increment = uu > 0.0 ? du / uu : 0.0;
      if (du <= tolerance_ * uu || r.norm() == 0.0) {
        x += z;  // the next correction, as good as the estimate
        result.converged = true;
        break;
      }
      const double rz_new = r.dot(z);
      p = z + (rz_new / rz) * p;
      rz = rz_new;
    }
  }
  F.scatter(x, up);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] += up[k];
  if (!exact && result.iterations > refactor_after_) stale_ = true;
  return result;
}

RelaxationResult DirectEquilibrium::solve_adjusting(const PdSolid& solid, std::vector<double>& u,
                                                    const std::vector<double>& dT,
                                                    const std::function<bool()>& adjust) {
  RelaxationResult total;
  for (;;) {
    const RelaxationResult r = solve(solid, u, dT);
    total.iterations += r.iterations;
    total.converged = r.converged;
    total.increment = r.increment;
    if (!adjust || !adjust()) return total;
  }
}

}  // namespace frostwall::pd
