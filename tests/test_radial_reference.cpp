// Story: the 1-D radial finite-volume reference (radial_reference.hpp) that
// the single-pipe SPH check compares with must itself be trustworthy:
//   - without phase change its steady state is the exact log profile;
//   - it conserves energy: the change of sum V_i H_i is the heat through the
//     boundaries;
//   - the frozen radius of the sand case converges as dr halves (and we
//     print the numbers the SPH check needs);
//   - for a huge pipe (curvature negligible) the front is the two-phase
//     Neumann similarity solution (Carslaw & Jaeger 11.2).
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fmt/core.h>

#include "radial_reference.hpp"

using namespace frostwall;

namespace {

constexpr double day = 86400.0;

project::Soil sand() { return *project::builtin_soil("sand"); }

test::RadialProblem sand_case() {
  return {.soil = sand(), .pipe_radius = 0.0635, .outer_radius = 3.0, .T_init = 15.0, .T_pipe = -20.0, .T_far = 15.0};
}

// Two-phase Neumann problem (Carslaw & Jaeger 11.2): solid 0 < x < X(t)
// with x = 0 held at T0 < Tf, liquid initially at Ti > Tf, X = 2 lambda
// sqrt(alpha_s t), lambda from
//   e^{-l^2}/erf(l) - (k_l sqrt(alpha_s) (Ti - Tf)) / (k_s sqrt(alpha_l) (Tf - T0))
//       * e^{-l^2 alpha_s/alpha_l} / erfc(l sqrt(alpha_s/alpha_l)) = l L sqrt(pi) / (c_s (Tf - T0)).
// With k = rho = c = 1 it is physics.md section 3's equation.
double neumann_lambda(const project::Soil& s, double T0, double Ti) {
  const double Tf = s.freezing_point;
  const double ks = s.frozen.conductivity[0], kl = s.unfrozen.conductivity[0];
  const double as = ks / (s.density * s.frozen.heat_capacity), al = kl / (s.density * s.unfrozen.heat_capacity);
  const double nu = std::sqrt(as / al);
  auto g = [&](double l) {
    return std::exp(-l * l) / std::erf(l) -
           kl * std::sqrt(as) * (Ti - Tf) / (ks * std::sqrt(al) * (Tf - T0)) * std::exp(-l * l * nu * nu) /
               std::erfc(l * nu) -
           l * s.latent_heat * std::sqrt(M_PI) / (s.frozen.heat_capacity * (Tf - T0));
  };
  double lo = 1e-6, hi = 5.0;  // g decreasing: +inf at 0, negative at 5
  for (int k = 0; k < 200; ++k) {
    const double c = 0.5 * (lo + hi);
    (g(c) > 0 ? lo : hi) = c;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("radial reference: steady state without phase change is the log profile", "[freezing][reference]") {
  auto soil = sand();
  soil.latent_heat = 0.0;
  soil.freezing_point = -1000.0;  // never reached: unfrozen throughout
  const test::RadialProblem p{
      .soil = soil, .pipe_radius = 0.0635, .outer_radius = 3.0, .T_init = 15.0, .T_pipe = -20.0, .T_far = 15.0};
  test::RadialReference ref(p, 0.001, {.growth = 0.05});
  ref.advance_to(1e10);  // some 4000 slowest decay times
  const double range = p.T_far - p.T_pipe, a = p.pipe_radius, R = p.outer_radius;
  double worst = 0.0;
  for (std::size_t i = 0; i < ref.cells(); ++i) {
    const double r = ref.cell_radius(i);
    const double exact = p.T_pipe + range * std::log(r / a) / std::log(R / a);
    worst = std::max(worst, std::abs(ref.temperature(i) - exact) / range);
  }
  for (double r : {a, 0.1, 0.5, 1.0, 2.0, R}) {
    const double exact = p.T_pipe + range * std::log(r / a) / std::log(R / a);
    worst = std::max(worst, std::abs(ref.temperature_at(r) - exact) / range);
  }
  fmt::print("radial reference, steady log profile (dr 1 mm, {} steps): worst error {:.2e} of the range\n", ref.steps(),
             worst);
  CHECK(worst < 1e-4);
  // Steady: the heat through the wall equals the heat through the far boundary,
  // 2 pi k (T_far - T_pipe) / ln(R/a) per metre (here per radian: without 2 pi).
  const double q_exact = soil.unfrozen.conductivity[0] * range / std::log(R / a);
  const double e0 = ref.energy(), w0 = ref.wall_heat();
  ref.advance_to(ref.time() + 1000.0);
  CHECK(std::abs((ref.wall_heat() - w0) / 1000.0 + q_exact) < 1e-3 * q_exact);
  CHECK(std::abs(ref.energy() - e0) < 1e-6 * q_exact * 1000.0 + 1e-9 * std::abs(e0));
}

TEST_CASE("radial reference: energy is conserved", "[freezing][reference]") {
  SECTION("adiabatic far field: the change of sum V H is the heat through the pipe wall") {
    auto p = sand_case();
    p.adiabatic_far = true;
    test::RadialReference ref(p, 0.004);
    const double e0 = ref.energy();
    for (double t : {1.0, 2.0, 5.0, 10.0, 20.0, 30.0}) {
      ref.advance_to(t * day);
      const double change = ref.energy() - e0;
      INFO("t = " << t << " d: change " << change << ", wall heat " << ref.wall_heat());
      CHECK(std::abs(change - ref.wall_heat()) <= 1e-9 * std::abs(ref.wall_heat()));
      CHECK(ref.far_heat() == 0.0);
      // The bookkeeping above holds by construction (H is updated from the
      // fluxes); that the state also solves the step's equations is this:
      CHECK(ref.last_step_residual() < 1e-6);
    }
    fmt::print("radial reference, energy (adiabatic far field, dr 4 mm, 30 d): wall heat {:.6e} J/(m rad), "
               "change of sum V H {:.6e}, relative mismatch {:.1e}; residual of the last step {:.1e}\n",
               ref.wall_heat(), ref.energy() - e0, std::abs(ref.energy() - e0 - ref.wall_heat()) / -ref.wall_heat(),
               ref.last_step_residual());
  }
  SECTION("fixed far field, a freezing range and a pipe temperature ramp: wall plus far heat") {
    auto p = sand_case();
    p.soil.freezing_range = 1.0;
    p.T_pipe_at = [](double t) { return std::max(-20.0, 15.0 - 35.0 * t / (2 * day)); };
    test::RadialReference ref(p, 0.004, {.dt_max = 3600.0});
    const double e0 = ref.energy();
    ref.advance_to(30 * day);
    const double boundary = ref.wall_heat() + ref.far_heat();
    CHECK(std::abs(ref.energy() - e0 - boundary) <= 1e-9 * std::abs(boundary));
    CHECK(ref.far_heat() != 0.0);
    CHECK(ref.last_step_residual() < 1e-6);
  }
}

TEST_CASE("radial reference: the frozen radius of the sand case converges", "[freezing][reference]") {
  // Two measures of the front: frozen_radius(), where f crosses 0.5 (the
  // definition the SPH front uses), and frozen_radius_by_volume(). With an
  // isothermal law one cell at a time is freezing, and interpolating f
  // between that cell and its neighbours puts the 0.5 crossing up to about
  // 0.08 dr off the cell's frozen share, back and forth as the front
  // crosses each cell: its successive differences need not shrink one by
  // one. The volume measure is smoother (the plain enthalpy method still
  // leaves it a smaller wobble of the same period, from the flux into the
  // freezing cell) and carries the order test; the crossing is held
  // within its wobble of it. Both must agree within 0.2 % at the finest two.
  const auto p = sand_case();
  const double spacings[] = {0.008, 0.004, 0.002, 0.001};
  const double days[] = {10.0, 20.0, 30.0};
  double crossing[4][3], volume[4][3];
  fmt::print("radial reference, sand, pipe a = 0.0635 m at -20 C, ground and far field (R = 3 m) 15 C, t = 30 d\n");
  fmt::print("  dr (mm)   cells   steps   frozen radius (m)   by volume (m)   change by volume   order   time (s)\n");
  for (int k = 0; k < 4; ++k) {
    const auto start = std::chrono::steady_clock::now();
    test::RadialReference ref(p, spacings[k]);
    for (int d = 0; d < 3; ++d) {
      ref.advance_to(days[d] * day);
      crossing[k][d] = ref.frozen_radius();
      volume[k][d] = ref.frozen_radius_by_volume();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string change, order;
    if (k >= 1) change = fmt::format("{:+.2e}", volume[k][2] - volume[k - 1][2]);
    if (k >= 2)
      order = fmt::format("{:.2f}", std::log2(std::abs(volume[k - 1][2] - volume[k - 2][2]) /
                                              std::abs(volume[k][2] - volume[k - 1][2])));
    fmt::print("  {:7.0f}   {:5}   {:5}   {:17.6f}   {:13.6f}   {:>16}   {:>5}   {:8.3f}\n", spacings[k] * 1e3,
               ref.cells(), ref.steps(), crossing[k][2], volume[k][2], change, order, seconds);
  }
  for (int d = 0; d < 3; ++d) {
    INFO("t = " << days[d] << " d");
    for (int k = 2; k < 4; ++k) {  // self-convergence, order roughly 1 (observed 0.6 to 2)
      const double coarse = std::abs(volume[k - 1][d] - volume[k - 2][d]);
      const double fine = std::abs(volume[k][d] - volume[k - 1][d]);
      CHECK(fine < coarse);
      CHECK(std::log2(coarse / fine) > 0.5);
    }
    for (int k = 1; k < 3; ++k)  // and the distance to the finest solution shrinks
      CHECK(std::abs(volume[k][d] - volume[3][d]) < std::abs(volume[k - 1][d] - volume[3][d]));
    for (int k = 0; k < 4; ++k) CHECK(std::abs(crossing[k][d] - volume[k][d]) < 0.1 * spacings[k]);
    CHECK(std::abs(volume[3][d] - volume[2][d]) < 0.002 * volume[3][d]);
    CHECK(std::abs(crossing[3][d] - crossing[2][d]) < 0.002 * crossing[3][d]);
  }
  fmt::print("  frozen radius by volume at 10 and 20 d:");
  for (int d = 0; d < 2; ++d)
    for (int k = 0; k < 4; ++k) fmt::print("{}{:.6f}", k == 0 ? (d == 0 ? " " : "; ") : ", ", volume[k][d]);
  fmt::print(" m (dr 8, 4, 2, 1 mm)\n");
  // The numbers the single-pipe SPH check compares with (finest spacing).
  fmt::print("radial reference, sand case at dr 1 mm: frozen radius from the pipe axis\n");
  for (int d = 0; d < 3; ++d)
    fmt::print(
        "  t = {:2.0f} d: f = 0.5 crossing {:.5f} m, by volume {:.5f} m (frozen thickness beyond the wall {:.5f} m)\n",
        days[d], crossing[3][d], volume[3][d], crossing[3][d] - p.pipe_radius);
}

TEST_CASE("radial reference: the time step is converged", "[freezing][reference]") {
  // The default step (dt = t dr / 1 m) against one eight times smaller: the
  // time error falls with dr and sits far below the 2 % of the SPH check.
  const auto p = sand_case();
  test::RadialReference coarse(p, 0.004), fine(p, 0.004, {.growth = 0.004 / 8});
  coarse.advance_to(30 * day);
  fine.advance_to(30 * day);
  const double rel = std::abs(coarse.frozen_radius_by_volume() - fine.frozen_radius_by_volume()) /
                     fine.frozen_radius_by_volume();
  fmt::print("radial reference, dr 4 mm, 30 d: frozen radius by volume {:.6f} m with the default step, {:.6f} m "
             "with step / 8 (relative {:.1e})\n",
             coarse.frozen_radius_by_volume(), fine.frozen_radius_by_volume(), rel);
  CHECK(rel < 1e-3);
}

TEST_CASE("radial reference: plane limit is the two-phase Neumann solution", "[freezing][reference]") {
  // A pipe of radius 1000 m: over a front depth of under a metre the
  // curvature is negligible (its effect is of order X / a, 0.06 % here;
  // with a = 100 m it is about 0.2 %). Far boundary 4 m out: the liquid
  // there is still undisturbed at 10 days.
  auto p = sand_case();
  p.pipe_radius = 1000.0;
  p.outer_radius = 1004.0;
  {  // the generalised equation reduces to physics.md's: lambda = 0.5 for its unit problem
    project::Soil unit{.name = "unit",
                       .density = 1,
                       .unfrozen = {{1, 1}, 1},
                       .frozen = {{1, 1}, 1},
                       .latent_heat = 1,
                       .freezing_point = 1.0};
    CHECK(neumann_lambda(unit, 0.1906, 1.2) == Approx(0.5).epsilon(2e-3));
  }
  const double lambda = neumann_lambda(p.soil, p.T_pipe, p.T_init);
  const double alpha_s = p.soil.frozen.conductivity[0] / (p.soil.density * p.soil.frozen.heat_capacity);
  test::RadialReference ref(p, 0.002);
  fmt::print("radial reference, plane limit (a = 1000 m, dr 2 mm), sand, lambda = {:.6f}\n", lambda);
  for (double d : {2.0, 5.0, 10.0}) {
    ref.advance_to(d * day);
    const double X = ref.frozen_radius() - p.pipe_radius;
    const double exact = 2.0 * lambda * std::sqrt(alpha_s * d * day);
    fmt::print("  t = {:2.0f} d: front {:.5f} m, Neumann {:.5f} m, relative error {:+.2e}\n", d, X, exact,
               (X - exact) / exact);
    CHECK(std::abs(X - exact) < 0.005 * exact);  // the brief asks 1 %
  }
}
