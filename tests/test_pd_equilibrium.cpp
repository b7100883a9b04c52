// Story: the direct equilibrium of the linear PD solid (pd/equilibrium.hpp)
// against what is known independently:
//  - a plate cooled by 9 K on rollers: the exact plane-strain displacement
//    -(1 + nu) alpha 9 (x, y), from rest, with one solve;
//  - a pre-cracked plate pulled by its top edge, with a disc of particles
//    held as one rigid group (a frozen pore riding on the plate): the
//    adaptive dynamic relaxation's answer at a tight tolerance, and no
//    force left on any particle the solve moves;
//  - the same crack held at 0.95 of its critical load breaks nothing;
//    pulled to 1.3 it runs, and the state returned is an equilibrium
//    where no intact bond is beyond its critical stretch.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>

#include "pd/equilibrium.hpp"
#include "pd/relaxation.hpp"
#include "pd/solid.hpp"
#include "pd_lattice.hpp"

using namespace frostwall;
using pd::Vec2;

namespace {

constexpr double E = 25.7e9, alpha = 1.8e-5;

project::Mechanics rollers() {
  project::Mechanics m;
  m.material.elastic_modulus = E;
  m.material.poisson_ratio = 0.25;
  m.material.thermal_expansion = alpha;
  m.left.kind = m.bottom.kind = project::Support::Kind::roller;
  return m;
}

// A plate with a central pre-crack, its top edge pulled by d, sides free.
std::unique_ptr<pd::PdSolid> pulled(double L, double dx, double d, double G0) {
  auto m = rollers();
  m.left.kind = m.right.kind = project::Support::Kind::free;
  m.top.kind = project::Support::Kind::displacement;
  m.top.uy = d;
  m.material.fracture_energy = G0;
  auto solid = std::make_unique<pd::PdSolid>(test::square_lattice(L, dx), m, pd::make_bond_law(m, 3.015 * dx));
  solid->cut(Vec2(0.35 * L, 0.5 * L + 1e-9), Vec2(0.65 * L, 0.5 * L + 1e-9));
  return solid;
}

// The force density of the linear kinematics the solve uses.
std::vector<double> linear_forces(const pd::PdSolid& solid, const std::vector<double>& u,
                                  const std::vector<double>& dT) {
  std::vector<double> u_all, dT_all, thermal, F;
  solid.extend(u, u_all);
  solid.extend_temperature(dT, dT_all);
  solid.thermal_force(dT_all, thermal);
  solid.forces_linear(u_all, thermal, F);
  return F;
}

// The largest force (density) on a particle the solve moves, and on
// a rigid group, against the largest bond force the load puts in.
double largest_unbalanced(const pd::PdSolid& solid, const std::vector<double>& u, const std::vector<double>& dT) {
  std::vector<double> F = linear_forces(solid, u, dT);
  double largest = 0.0;
  for (std::size_t i = 0; i < solid.size(); ++i)
    if (solid.moves(i)) largest = std::max(largest, std::hypot(F[2 * i], F[2 * i + 1]));
  for (const auto& group : solid.groups()) {
    Vec2 sum = Vec2::Zero();
    for (std::size_t i : group) sum += Vec2(F[2 * i], F[2 * i + 1]);
    largest = std::max(largest, sum.norm());
  }
  return largest;
}

double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0, scale = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    d = std::max(d, std::abs(a[k] - b[k]));
    scale = std::max(scale, std::abs(b[k]));
  }
  return d / scale;
}

}  // namespace

TEST_CASE("PD direct equilibrium: the cooled plate's exact displacement in one solve",
          "[pd][mechanics][verification]") {
  const double L = 0.01, dx = L / 30;
  const auto m = rollers();
  const pd::PdSolid solid(test::square_lattice(L, dx), m, pd::make_bond_law(m, 3.015 * dx));
  const std::vector<double> dT(solid.size(), -9.0);
  const double k = -(1.0 + 0.25) * alpha * 9.0;
  std::vector<double> u(2 * solid.size(), 0.0);
  pd::DirectEquilibrium direct;
  const auto r = direct.solve(solid, u, dT);
  double error = 0.0;
  for (std::size_t i = 0; i < solid.size(); ++i)
    error = std::max(error, (Vec2(u[2 * i], u[2 * i + 1]) - k * solid.position()[i]).norm() / (std::abs(k) * L));
  fmt::print(
      "PD direct equilibrium, cooled plate 30 x 30: {} CG iterations, {} factorization, max |u - exact| / |u(A)| {:.2e}\n",
      r.iterations, direct.factorizations(), error);
  REQUIRE(r.converged);
  CHECK(r.iterations <= 3);  // the factor is of this very K
  CHECK(error < 1e-6);
}

TEST_CASE("PD direct equilibrium: a pulled pre-crack and a rigid group, as the relaxation finds them",
          "[pd][mechanics]") {
  const double L = 0.01, dx = L / 30, d = 1e-7;
  auto solid = pulled(L, dx, d, 50.0);
  // A disc of particles held as one rigid group, pushed out radially by
  // 1e-8 m (a freezing pore): the solve must find its translation.
  const Vec2 centre(0.3 * L, 0.25 * L);
  const double radius = 0.08 * L;
  std::vector<std::uint8_t> held(solid->size(), 0);
  std::vector<std::size_t> group;
  std::vector<double> start(2 * solid->size(), 0.0);
  for (std::size_t i = 0; i < solid->size(); ++i) {
    const Vec2 r = solid->position()[i] - centre;
    if (r.norm() > radius) continue;
    held[i] = 1;
    group.push_back(i);
    start[2 * i] = 1e-8 * r[0] / radius;
    start[2 * i + 1] = 1e-8 * r[1] / radius;
  }
  solid->set_held(held);
  solid->set_groups({group});
  const std::vector<double> dT(solid->size(), -5.0);
  std::vector<double> u_direct = start, u_relaxed = start;
  pd::DirectEquilibrium direct;
  const auto r = direct.solve(*solid, u_direct, dT);
  const auto a = pd::relax(*solid, u_relaxed, dT, 1e-11, 400000);
  REQUIRE(r.converged);
  REQUIRE(a.converged);
  const std::vector<double> F0 = linear_forces(*solid, start, dT);
  double load = 0.0;
  for (double f : F0) load = std::max(load, std::abs(f));
  const double unbalanced = largest_unbalanced(*solid, u_direct, dT) / load;
  const double difference = largest_difference(u_direct, u_relaxed);
  fmt::print("PD direct equilibrium, pulled pre-crack with a rigid group: {} CG iterations against {} ADR iterations; "
             "largest force left {:.1e} of the starting one; max |u_direct - u_ADR| / max |u| {:.1e}\n",
             r.iterations, a.iterations, unbalanced, difference);
  CHECK(unbalanced < 1e-6);
  CHECK(difference < 1e-5);
}

TEST_CASE("PD direct equilibrium: a crack runs at a fixed load and stops where no bond is beyond critical",
          "[pd][mechanics][fracture]") {
  const double L = 0.01, dx = L / 40, G0 = 50.0;
  const std::vector<double> dT(40 * 40, 0.0);
  // The critical load by linearity, as in test_pd_solid.cpp.
  auto probe = pulled(L, dx, 1e-7, G0);
  std::vector<double> u0(2 * probe->size(), 0.0);
  pd::DirectEquilibrium().solve(*probe, u0, dT);
  const double d_critical = 1e-7 * probe->law().critical_stretch / probe->largest_stretch(u0, dT);
  // Below the critical load nothing breaks; above it the crack runs, each
  // round an equilibrium, until no intact bond is beyond critical.
  for (const double factor : {0.95, 1.3}) {
    auto solid = pulled(L, dx, factor * d_critical, G0);
    std::vector<double> u(2 * solid->size(), 0.0);
    pd::DirectEquilibrium direct;
    std::size_t count = 0;
    auto adjust = [&] {
      const std::size_t now = solid->break_bonds(u, dT);
      count += now;
      return now > 0;
    };
    REQUIRE(direct.solve_adjusting(*solid, u, dT, adjust).converged);
    double over = 0.0;
    for (double s : solid->breakable_stretches(u, dT)) over = std::max(over, s / solid->law().critical_stretch);
    fmt::print("PD crack at {} x its critical load: {} bonds broken in {} equilibria ({} factorizations), "
               "largest stretch / critical {:.4f}\n",
               factor, count, direct.solves(), direct.factorizations(), over);
    CHECK(over <= 1.0 + 1e-9);
    if (factor < 1.0) CHECK(count == 0);
    else CHECK(count > 10);
  }
}

TEST_CASE(
    "PD direct equilibrium: a crack cascade solved by preconditioned CG breaks what K's own factor every round breaks",
    "[pd][mechanics][fracture]") {
  // A disc of held particles pushed out radially in small steps (a pore
  // as it freezes) in a plate on rollers; radial cracks run from it, in
  // rounds at each step. The reference factors K after every round, so
  // each equilibrium is a direct solve; the default reuses an old factor
  // as CG's preconditioner.
  const double L = 0.01, dx = L / 36, G0 = 30.0, R = 0.15 * L;
  const Vec2 centre(0.41 * L, 0.43 * L);
  const std::vector<double> dT(36 * 36, 0.0);
  auto run = [&](pd::DirectEquilibrium direct) {
    auto m = rollers();
    m.material.fracture_energy = G0;
    pd::PdSolid solid(test::square_lattice(L, dx), m, pd::make_bond_law(m, 3.015 * dx));
    std::vector<std::uint8_t> held(solid.size(), 0);
    for (std::size_t i = 0; i < solid.size(); ++i) held[i] = (solid.position()[i] - centre).norm() <= R;
    solid.set_held(held);
    std::vector<double> u(2 * solid.size(), 0.0);
    std::size_t count = 0;
    auto adjust = [&] {
      const std::size_t now = solid.break_bonds(u, dT);
      count += now;
      return now > 0;
    };
    for (int step = 1; step <= 20; ++step) {
      const double strain = 0.2 * step * solid.law().critical_stretch;  // to 4 x critical
      for (std::size_t i = 0; i < solid.size(); ++i)
        if (held[i]) {
          const Vec2 r = solid.position()[i] - centre;
          u[2 * i] = strain * r[0];
          u[2 * i + 1] = strain * r[1];
        }
      REQUIRE(direct.solve_adjusting(solid, u, dT, adjust).converged);
    }
    fmt::print(
        "PD disc pushed to 4 x critical hoop strain in 20 steps: {} bonds broken, {} equilibria, {} factorizations\n",
        count, direct.solves(), direct.factorizations());
    return count;
  };
  const std::size_t reference = run(pd::DirectEquilibrium(1e-8, 0)), preconditioned = run(pd::DirectEquilibrium());
  REQUIRE(reference > 100);
  CHECK(std::abs(double(preconditioned) - double(reference)) <= 0.01 * double(reference));
}
