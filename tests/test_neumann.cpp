// Story: the Neumann (one-phase Stefan) problem of the SPH paper, section
// 2.1. Liquid at Ti = 1.2 above its freezing point Tf = 1.0 is cooled from
// x = 0 held at T0 = 0.1906; k = rho = C = L = 1. Exact answer: the front
// is at X = 2 lambda sqrt(t) with lambda from the transcendental equation
// (0.5 here, so X = sqrt(t)), temperatures erf/erfc profiles (Carslaw &
// Jaeger 11.2). Tolerance: 1 % on the front at the finest spacing (the
// acceptance tolerance; the paper's SPH reached 1.2 %), and the error must fall
// as the spacing halves twice: a wrong flux or latent-heat balance shows
// as an error that stalls.
#include <catch2/catch.hpp>
#include <cmath>

#include "post/front.hpp"
#include "post/isoline.hpp"
#include "support.hpp"

using namespace frostwall;

namespace {

constexpr double T0 = 0.1906, Tf = 1.0, Ti = 1.2;

double lambda_exact() {  // bisection on the Neumann equation with k = rho = C = L = 1
  auto g = [](double l) {
    return std::erf(l) * std::exp(l * l) * (l * std::sqrt(M_PI) + (Ti - Tf) * std::exp(-l * l) / std::erfc(l)) -
           (Tf - T0);
  };
  double a = 1e-3, b = 3.0;
  for (int k = 0; k < 200; ++k) {
    const double c = 0.5 * (a + b);
    (g(a) * g(c) <= 0 ? b : a) = c;
  }
  return 0.5 * (a + b);
}

double exact_temperature(double x, double t, double lambda) {
  const double s = x / (2.0 * std::sqrt(t));
  if (s < lambda) return T0 + (Tf - T0) * std::erf(s) / std::erf(lambda);
  return Ti + (Tf - Ti) * std::erfc(s) / std::erfc(lambda);
}

struct NeumannResult {
  double isoline_error;          // relative, the 0.5 isoline's mean x against 2 lambda sqrt(t) at t = 0.15
  double front_error[2];         // relative, at t = 0.10 and 0.15
  double rms_front_error;        // relative, over 40 instants in [0.025, 0.15]
  double max_temperature_error;  // at t = 0.15, over the particles
  std::vector<double> front;     // X at the 40 instants
};

NeumannResult solve_neumann(double dx, double lambda, const std::string& numerics = "") {
  // A strip two rows high (mirrors top and bottom make it 1-D), 1.5 long:
  // at t = 0.15 the liquid far end has moved by 1e-3 of the range.
  const auto p = test::rectangle_project(
      1.5, 2 * dx,
      R"({ "left": { "temperature": 0.1906 }, "right": { "temperature": 1.2 }, "top": "adiabatic", "bottom": "adiabatic" })",
      test::unit_soil(Tf, 1.0), Ti, 0.15, numerics.empty() ? test::numerics(dx) : numerics);
  auto m = freezing::build_model(p);
  NeumannResult r{};
  std::vector<double> times;
  for (int k = 1; k <= 40; ++k) times.push_back(0.025 + k * 0.125 / 40);  // ends on 0.10 (k = 24) and 0.15
  double sum_squares = 0.0;
  test::march(m, times, [&](std::size_t k) {
    const double t = times[k];
    const auto X =
        post::frozen_front(m.particles().position, m.model->liquid_fraction(), m.model->free_count(), *m.face);
    REQUIRE(X);
    const double exact = 2.0 * lambda * std::sqrt(t);
    const double error = std::abs(*X - exact) / exact;
    r.front.push_back(*X);
    sum_squares += error * error;
    if (std::abs(t - 0.10) < 1e-12) r.front_error[0] = error;
    if (k == times.size() - 1) {
      // The front curve (as written to interface files) is a second measure.
      const auto lines = post::isolines(m.particles().position, m.model->liquid_fraction(), 0.5, 3 * dx);
      double sum = 0.0;
      std::size_t count = 0;
      for (const auto& line : lines)
        for (const auto& x : line.points) sum += x[0], ++count;
      r.isoline_error = count ? std::abs(sum / count - exact) / exact : 1.0;
      r.front_error[1] = error;
      r.rms_front_error = std::sqrt(sum_squares / times.size());
      for (std::size_t i = 0; i < m.model->free_count(); ++i) {
        const double x = m.particles().position[i][0];
        if (x > 1.0) continue;  // far field: the semi-infinite solution does not see the far end
        r.max_temperature_error =
            std::max(r.max_temperature_error, std::abs(m.model->temperature()[i] - exact_temperature(x, t, lambda)));
      }
    }
  });
  return r;
}

}  // namespace

TEST_CASE("Neumann problem: lambda of the transcendental equation is 0.5", "[freezing][verification][neumann]") {
  CHECK(lambda_exact() == Approx(0.5).margin(2e-4));
}

TEST_CASE("Neumann problem: front within 1 % of sqrt(t) and converging", "[freezing][verification][neumann]") {
  const double lambda = lambda_exact();
  const std::vector<double> spacings{0.01, 0.005, 0.0025};
  std::vector<NeumannResult> results;
  for (double dx : spacings) results.push_back(solve_neumann(dx, lambda));

  fmt::print("\nNeumann problem, front X(t) against 2 lambda sqrt(t), lambda = {:.5f}\n", lambda);
  fmt::print("  spacing   err X(0.10)  err X(0.15)  rms err X(t)  max |T - T_exact| at 0.15\n");
  for (std::size_t k = 0; k < spacings.size(); ++k)
    fmt::print("  {:<8}  {:9.4f} %  {:9.4f} %  {:9.4f} %   {:.5f}\n", spacings[k], 100 * results[k].front_error[0],
               100 * results[k].front_error[1], 100 * results[k].rms_front_error, results[k].max_temperature_error);

  const auto& finest = results.back();
  CHECK(finest.front_error[0] < 0.01);
  CHECK(finest.front_error[1] < 0.01);
  fmt::print("  front curve (isoline) at t = 0.15, finest spacing: error {:.4f} %\n", 100 * finest.isoline_error);
  CHECK(finest.isoline_error < 0.01);
  // The error falls as the spacing halves. At one instant it wobbles as the
  // front crosses particle rows (a stair of one spacing), so the trend is
  // judged on the rms over the run.
  for (std::size_t k = 1; k < results.size(); ++k) CHECK(results[k].rms_front_error < results[k - 1].rms_front_error);
  // Temperatures: within 1 % of the 1.0 K range at the finest spacing, and falling.
  CHECK(finest.max_temperature_error < 0.01);
  CHECK(results.back().max_temperature_error < results.front().max_temperature_error);
}

// Story: the same problem with the integrators that choose their own step
// (RKL2 super-time-stepping, the default, and backward Euler). At one
// spacing the explicit run, with its step ~1000x shorter, is the
// time-converged answer of the same particles; the difference to it is the
// time error. It must fall as step_change (the enthalpy change allowed per
// step) falls by 4x twice, and at the default (0.25) the front must stay
// within the 1 % of the exact solution that the explicit run meets.
// (Measured: rkl2 0.052 / 0.026 / 0.006 %, implicit 0.36 / 0.084 / 0.005 %;
// step_change above 1 changes nothing here, the 40 output instants then
// set the step; below 1/16 both reach the explicit run's own ~0.005 %.)
TEST_CASE("Neumann problem with the adaptive-step integrators: time error falls with the step",
          "[freezing][verification][neumann]") {
  const double lambda = lambda_exact();
  const double dx = 0.005;
  const NeumannResult reference = solve_neumann(dx, lambda);
  std::vector<double> exact;
  for (int k = 1; k <= 40; ++k) exact.push_back(2.0 * lambda * std::sqrt(0.025 + k * 0.125 / 40));
  for (const std::string integrator : {"rkl2", "implicit"}) {
    fmt::print("\nNeumann problem, {} at spacing {}: front against the explicit run (time error)\n", integrator, dx);
    fmt::print("  step_change  rms time error  err X(0.15) vs exact\n");
    std::vector<double> time_error;
    for (double change : {1.0, 0.25, 0.0625}) {
      const NeumannResult r = solve_neumann(dx, lambda, test::numerics(dx, "renormalised", integrator, change));
      REQUIRE(r.front.size() == reference.front.size());
      double sum = 0.0;
      for (std::size_t k = 0; k < r.front.size(); ++k) sum += std::pow((r.front[k] - reference.front[k]) / exact[k], 2);
      time_error.push_back(std::sqrt(sum / r.front.size()));
      fmt::print("  {:<11}  {:10.4f} %    {:8.4f} %\n", change, 100 * time_error.back(), 100 * r.front_error[1]);
      if (change == 0.25) {
        CHECK(r.front_error[0] < 0.01);
        CHECK(r.front_error[1] < 0.01);
      }
    }
    for (std::size_t k = 1; k < time_error.size(); ++k) CHECK(time_error[k] < time_error[k - 1]);
  }
}

// Story: the same problem on a graded cloud (placement "graded": finest
// spacing at the cooled face and in the band the front crosses, coarser
// beyond; CVT points, not a lattice), in a strip 0.1 high so the cloud is
// truly 2-D. Same exact answer, same 1 % tolerance; the front's rms error
// must fall as the finest spacing halves.
TEST_CASE("Neumann problem on a graded cloud: front within 1 %", "[freezing][verification][neumann][graded]") {
  const double lambda = lambda_exact();
  std::vector<double> times;
  for (int k = 1; k <= 40; ++k) times.push_back(0.025 + k * 0.125 / 40);
  fmt::print(
      "\nNeumann problem on a graded cloud (rkl2)\n  finest spacing  particles  err X(0.10)  err X(0.15)  rms err\n");
  std::vector<double> rms;
  for (double dx : {0.01, 0.005}) {
    const auto p = test::rectangle_project(
        1.5, 0.1,
        R"({ "left": { "temperature": 0.1906 }, "right": { "temperature": 1.2 }, "top": "adiabatic", "bottom": "adiabatic" })",
        test::unit_soil(Tf, 1.0), Ti, 0.15,
        fmt::format(R"({{ "spacing": {}, "integrator": "rkl2", "placement": "graded" }})", dx));
    auto m = freezing::build_model(p);
    double sum = 0.0, err10 = 1.0, err15 = 1.0;
    test::march(m, times, [&](std::size_t k) {
      const auto X =
          post::frozen_front(m.particles().position, m.model->liquid_fraction(), m.model->free_count(), *m.face);
      REQUIRE(X);
      const double exact = 2.0 * lambda * std::sqrt(times[k]);
      const double error = std::abs(*X - exact) / exact;
      sum += error * error;
      if (k == 23) err10 = error;
      if (k == times.size() - 1) err15 = error;
    });
    rms.push_back(std::sqrt(sum / times.size()));
    fmt::print("  {:<14}  {:9}  {:9.4f} %  {:9.4f} %  {:7.4f} %\n", dx, m.model->free_count(), 100 * err10, 100 * err15,
               100 * rms.back());
    if (dx == 0.005) {
      CHECK(err10 < 0.01);
      CHECK(err15 < 0.01);
    }
  }
  CHECK(rms[1] < rms[0]);
}
