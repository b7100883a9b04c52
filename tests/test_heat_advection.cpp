// Heat carried by groundwater on the particle
// pairs (thermal/heat_advection.hpp) with the Darcy solver's own pair
// fluxes (groundwater/darcy_cloud.hpp).
//  - 1-D advection-conduction between two fixed-temperature faces, steady:
//    T = T0 + (T1 - T0) (e^(Pe x/L) - 1) / (e^Pe - 1), Pe = rho_w c_w q L / lambda,
//    within 1 % with the limited scheme (second order), several times
//    closer than first-order upwind;
//  - no new extremum at a sharp front (monotone upwind);
//  - energy: stored heat changes by what conduction and the water bring
//    in through the faces, to round-off, every step.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>

#include "groundwater/darcy_cloud.hpp"
#include "sph/kernel.hpp"
#include "sph/laplacian.hpp"
#include "sph/wall_extrapolation.hpp"
#include "thermal/backward_euler.hpp"
#include "thermal/heat_advection.hpp"
#include "thermal/integrator.hpp"
#include "no_phase_change_soil.hpp"

using namespace frostwall;
using particles::Vec;

namespace {

constexpr double L = 1.0, W = 0.1;
constexpr double lambda = 2.0, rho_c = 2.0e6, rho_c_w = 4.2e6;  // W/(m K), J/(m3 K)
constexpr double T0 = 0.0, T1 = 1.0;

struct Strip {
  particles::ParticleSet<2> cloud;
  particles::PairWeights pairs;
  std::unique_ptr<thermal::ThermalModel> model;
  std::unique_ptr<groundwater::DarcyCloud> darcy;
};

// A strip [0, L] x [0, W], its long sides mirror planes; beyond x = 0 and
// x = L bands of fixed particles at T0 and T1. Water flows along +x at q.
Strip make_strip(double s, double q, double initial) {
  Strip strip;
  auto& cloud = strip.cloud;
  const double h = 1.3 * s, band = 2.0 * h + s;
  for (double x = -band + 0.5 * s; x < L + band; x += s)
    for (double y = 0.5 * s; y < W; y += s) {
      // Beyond a face: the antisymmetric image of the point across it, so
      // the face sits at x = 0 and x = L exactly (as the shaft's walls do).
      if (x < 0.0) cloud.add(Vec<2>(x, y), s * s, 0, Vec<2>(-x, y));
      else if (x > L) cloud.add(Vec<2>(x, y), s * s, 1, Vec<2>(2.0 * L - x, y));
      else cloud.add(Vec<2>(x, y), s * s, -1);
    }
  cloud.spacing = s;
  cloud.mirrors = {{Vec<2>(0.0, 0.0), Vec<2>(0.0, 1.0)}, {Vec<2>(0.0, W), Vec<2>(0.0, -1.0)}};
  cloud.order_free_first();
  const sph::WendlandC2<2> kernel;
  strip.pairs =
      sph::build_laplacian_pairs<2>(cloud, kernel, {h, project::LaplacianForm::renormalised, false, false, true});
  std::vector<double> fixed;
  for (std::size_t j = cloud.n_free; j < cloud.size(); ++j) fixed.push_back(-q * cloud.position[j][0]);
  strip.darcy = std::make_unique<groundwater::DarcyCloud>(strip.pairs, cloud.volume, fixed);
  strip.darcy->solve(std::vector<double>(cloud.size(), 1.0));
  std::vector<geometry::FixedTemperatureBoundary> faces = {{"inflow", project::TemperatureSchedule::fixed(T0)},
                                                           {"outflow", project::TemperatureSchedule::fixed(T1)}};
  strip.model = std::make_unique<thermal::ThermalModel>(
      cloud.volume, cloud.boundary, strip.pairs,
      thermal::PhaseChangeLaw(test::no_phase_change_soil("test", lambda, rho_c)), faces, thermal::ConductionOptions{},
      initial, sph::build_wall_extrapolation<2>(cloud, kernel, h));
  return strip;
}

double exact(double x, double q) {
  const double Pe = rho_c_w * q * L / lambda;
  return T0 + (T1 - T0) * std::expm1(Pe * x / L) / std::expm1(Pe);
}

// Runs to steady state (Strang: half the water's heat, conduction, half);
// returns the worst |T - exact| / (T1 - T0).
// `courant`: the water's step in upwind stable steps (0: the conduction's
// step), conduction sub-stepped within it.
double steady_error(double s, double q, thermal::AdvectionScheme scheme, double courant = 0.0) {
  Strip strip = make_strip(s, q, 0.5);
  auto& model = *strip.model;
  thermal::HeatAdvection water(rho_c_w, strip.darcy->pair_flux(), scheme);
  thermal::ExplicitEuler conduction(0.1, 1.3 * s);
  const double explicit_step = conduction.preferred_step(model), end = 6.0 * L * L * rho_c / lambda;
  const double dt = courant > 0.0 ? courant * thermal::HeatAdvection(rho_c_w, strip.darcy->pair_flux(),
                                                                     thermal::AdvectionScheme::upwind)
                                                  .stable_step(model)
                                  : explicit_step;
  const int substeps = int(std::ceil(dt / explicit_step - 1e-9));
  auto conduct = [&](thermal::ThermalModel& m, double t0, double h) {
    std::vector<double> heat(2, 0.0);
    for (int k = 0; k < substeps; ++k) {
      const auto part = conduction.advance(m, t0 + k * h / substeps, h / substeps);
      for (int b = 0; b < 2; ++b) heat[b] += part[b];
      m.apply_boundaries(t0 + (k + 1) * h / substeps);
    }
    return heat;
  };
  model.apply_boundaries(0.0);
  for (double t = 0.0; t < end; t += dt) {
    water.advance(model, t, 0.5 * dt);
    conduct(model, t, dt);
    water.advance(model, t + 0.5 * dt, 0.5 * dt);
    model.apply_boundaries(t + dt);
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < model.free_count(); ++i)
    worst = std::max(worst, std::abs(model.temperature()[i] - exact(strip.cloud.position[i][0], q)) / (T1 - T0));
  return worst;
}

// The coupled scheme: water and conduction in one backward-Euler step of
// `courant` upwind stable steps, to steady state. Returns the worst error
// and adds the Newton iterations per step to `newton`.
double coupled_steady_error(double s, double q, double courant, double* newton = nullptr) {
  Strip strip = make_strip(s, q, 0.5);
  auto& model = *strip.model;
  thermal::HeatAdvection water(rho_c_w, strip.darcy->pair_flux(), thermal::AdvectionScheme::coupled);
  thermal::BackwardEuler step({}, 1.0);
  step.couple(&water);
  const double dt =
      courant *
      thermal::HeatAdvection(rho_c_w, strip.darcy->pair_flux(), thermal::AdvectionScheme::upwind).stable_step(model);
  const double end = 6.0 * L * L * rho_c / lambda;
  model.apply_boundaries(0.0);
  for (double t = 0.0; t < end; t += dt) step.advance(model, t, dt), model.apply_boundaries(t + dt);
  if (newton) *newton = double(step.statistics().newton_iterations) / double(step.statistics().steps);
  double worst = 0.0;
  for (std::size_t i = 0; i < model.free_count(); ++i)
    worst = std::max(worst, std::abs(model.temperature()[i] - exact(strip.cloud.position[i][0], q)) / (T1 - T0));
  return worst;
}

}  // namespace

TEST_CASE("Coupled water and conduction: the steady profile within 1 % at any step, second order",
          "[freezing][groundwater][advection]") {
  // One backward-Euler system for both: its steady state is the discrete
  // balance itself, so the step (Courant 1 to 100) must not move it; the
  // limited faces keep second order (20 -> 40 particles across).
  const double q = 3.0 * lambda / (rho_c_w * L);  // Peclet 3
  double newton_1 = 0.0, newton_100 = 0.0;
  const double at_1 = coupled_steady_error(L / 20.0, q, 1.0, &newton_1);
  const double at_10 = coupled_steady_error(L / 20.0, q, 10.0);
  const double at_100 = coupled_steady_error(L / 20.0, q, 100.0, &newton_100);
  const double fine = coupled_steady_error(L / 40.0, q, 10.0);
  const double explicit_limited = steady_error(L / 20.0, q, thermal::AdvectionScheme::limited);
  INFO(fmt::format(
      "worst error {:.5f} / {:.5f} / {:.5f} at Courant 1 / 10 / 100, {:.5f} at 40 across; explicit limited {:.5f}; "
      "Newton iterations a step {:.1f} at Courant 1, {:.1f} at 100",
      at_1, at_10, at_100, fine, explicit_limited, newton_1, newton_100));
  CHECK(at_10 < 0.01);
  CHECK(std::abs(at_100 - at_1) < 1e-4);
  CHECK(std::abs(at_10 - explicit_limited) < 0.2 * explicit_limited);
  CHECK(fine < 0.35 * at_10);
}

TEST_CASE("Advection-conduction between two faces reaches the exponential profile within 1 %",
          "[freezing][groundwater][advection]") {
  // Limited: second order (the error falls about fourfold from 20 to 40
  // particles across). Upwind converges too, but its own diffusion,
  // rho_w c_w q s / 2, keeps it several times further off.
  const double q = 3.0 * lambda / (rho_c_w * L);  // Peclet 3
  const double coarse = steady_error(L / 20.0, q, thermal::AdvectionScheme::limited);
  const double fine = steady_error(L / 40.0, q, thermal::AdvectionScheme::limited);
  const double upwind_coarse = steady_error(L / 20.0, q, thermal::AdvectionScheme::upwind);
  const double upwind_fine = steady_error(L / 40.0, q, thermal::AdvectionScheme::upwind);
  INFO(fmt::format("worst error, limited {:.5f} (20 across) -> {:.5f} (40 across); upwind {:.5f} -> {:.5f}", coarse,
                   fine, upwind_coarse, upwind_fine));
  CHECK(fine < 0.01);
  CHECK(fine < 0.35 * coarse);
  CHECK(upwind_fine < 0.7 * upwind_coarse);
  CHECK(fine < 0.3 * upwind_fine);
  // Implicit (screening), the water stepped at Courant 1 and 4: upwind, and
  // split from the conduction at a long step, so its steady state moves
  // with the step; it must come back as the step shrinks.
  const double implicit_1 = steady_error(L / 20.0, q, thermal::AdvectionScheme::implicit, 1.0);
  const double implicit_4 = steady_error(L / 20.0, q, thermal::AdvectionScheme::implicit, 4.0);
  WARN(fmt::format("implicit: worst error {:.5f} at Courant 1, {:.5f} at 4 (upwind explicit {:.5f})", implicit_1,
                   implicit_4, upwind_coarse));
  CHECK(implicit_1 < 0.5 * implicit_4);
}

TEST_CASE("The water's heat: a sharp front makes no new extremum, and energy balances every step",
          "[freezing][groundwater][advection]") {
  // The implicit scheme at Courant 1, 4 and 10 (its step in upwind stable
  // steps; the explicit ones at the conduction's step, within theirs).
  using S = thermal::AdvectionScheme;
  for (auto [scheme, courant] : {std::pair{S::upwind, 0.0},
                                 {S::limited, 0.0},
                                 {S::implicit, 1.0},
                                 {S::implicit, 4.0},
                                 {S::implicit, 10.0},
                                 {S::coupled, 1.0},
                                 {S::coupled, 4.0},
                                 {S::coupled, 10.0}}) {
    const double s = L / 40.0, q = 20.0 * lambda / (rho_c_w * L);  // Peclet 20: a sharp front
    Strip strip = make_strip(s, q, T1);                            // warm ground, cold water entering
    auto& model = *strip.model;
    thermal::HeatAdvection water(rho_c_w, strip.darcy->pair_flux(), scheme);
    thermal::ExplicitEuler explicit_conduction(0.1, 1.3 * s);
    thermal::BackwardEuler implicit_conduction({}, 1.0);  // the coupled scheme's step, water included
    implicit_conduction.couple(&water);
    thermal::Integrator& conduction = scheme == S::coupled ? static_cast<thermal::Integrator&>(implicit_conduction)
                                                           : explicit_conduction;
    const double dt = courant > 0.0
                          ? courant *
                                thermal::HeatAdvection(rho_c_w, strip.darcy->pair_flux(), S::upwind).stable_step(model)
                          : explicit_conduction.preferred_step(model);
    const int substeps = scheme == S::coupled ? 1
                                              : int(std::ceil(dt / explicit_conduction.preferred_step(model) - 1e-9));
    model.apply_boundaries(0.0);
    double stored = model.stored_heat(), worst_balance = 0.0, scale = 0.0;
    double lowest = 1e9, highest = -1e9;
    for (int k = 0; k < (courant > 0.0 ? 40 : 400); ++k) {
      const auto in_water = water.advance(model, k * dt, dt);
      std::vector<double> in_conduction(2, 0.0);
      for (int m = 0; m < substeps; ++m) {
        const auto part = conduction.advance(model, k * dt + m * dt / substeps, dt / substeps);
        for (int b = 0; b < 2; ++b) in_conduction[b] += part[b];
        if (m + 1 < substeps) model.apply_boundaries(k * dt + (m + 1) * dt / substeps);
      }
      model.apply_boundaries((k + 1) * dt);
      const double now = model.stored_heat();
      const double brought = in_water[0] + in_water[1] + in_conduction[0] + in_conduction[1];
      scale = std::max(scale, std::abs(brought));
      worst_balance = std::max(worst_balance, std::abs(now - stored - brought));
      stored = now;
      for (std::size_t i = 0; i < model.free_count(); ++i)
        lowest = std::min(lowest, model.temperature()[i]), highest = std::max(highest, model.temperature()[i]);
    }
    INFO((scheme == S::upwind     ? "upwind"
          : scheme == S::limited  ? "limited"
          : scheme == S::implicit ? "implicit"
                                  : "coupled")
         << " Courant " << courant);
    INFO(fmt::format("balance {:.3g} J of {:.3g} J a step; T in [{:.6f}, {:.6f}]", worst_balance, scale, lowest,
                     highest));
    // The coupled step balances to its Newton tolerance (each particle's
    // residual below 1e-7 of the enthalpy scale over the step), the others
    // to round-off.
    double area = 0.0;
    for (std::size_t i = 0; i < model.free_count(); ++i) area += model.volume()[i];
    const double newton_bound = thermal::BackwardEulerSettings{}.newton_tolerance *
                                thermal::ActivityStepControl::enthalpy_scale(model) * area;
    CHECK(worst_balance < (scheme == S::coupled ? newton_bound : 1e-9 * scale));
    CHECK(lowest >= T0 - 1e-9);  // the front has arrived: something below T1
    CHECK(lowest < 0.5 * (T0 + T1));
    CHECK(highest <= T1 + 1e-9);
  }
}
