// Story: pure conduction (no latent heat: the freezing point is far below
// every temperature), against exact solutions.
// 1. An insulated unit square holding the mode cos(pi x) cos(pi y): it
//    decays as exp(-2 pi^2 alpha t) and nothing else. The renormalised
//    Laplacian is second order on a lattice (observed order >= 1.8 asserted);
//    the plain SPH form keeps a lattice-sum error at fixed h/spacing and
//    stalls (printed for contrast, asserted to be far worse).
// 2. A half-space suddenly cooled at x = 0: T = Ti erf(x / (2 sqrt(alpha t))).
//    Fixed particles hold the face; the error must fall with the spacing.
#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

using namespace frostwall;

namespace {

const std::string insulated = R"({ "left": "adiabatic", "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })";

double sine_mode_error(double dx, const std::string& laplacian) {
  const double t_end = 0.05;
  auto p = test::rectangle_project(1.0, 1.0, insulated, test::unit_soil(-100.0, 0.0), 5.0, t_end,
                                   test::numerics(dx, laplacian));
  auto m = run::build_model(p);
  const auto& x = m.particles().position;
  auto mode = [&](std::size_t i) { return std::cos(M_PI * x[i][0]) * std::cos(M_PI * x[i][1]); };
  for (std::size_t i = 0; i < m.model->free_count(); ++i) m.model->set_enthalpy(i, m.model->law().enthalpy(5.0 + mode(i)));
  double error = 0.0;
  test::march(m, {t_end}, [&](std::size_t) {
    const double decay = std::exp(-2.0 * M_PI * M_PI * t_end);
    for (std::size_t i = 0; i < m.model->free_count(); ++i)
      error = std::max(error, std::abs(m.model->temperature()[i] - (5.0 + decay * mode(i))));
  });
  return error;
}

}  // namespace

TEST_CASE("Insulated sine mode decays as exp(-2 pi^2 t), second order", "[verification][conduction]") {
  const std::vector<double> spacings{1.0 / 10, 1.0 / 20, 1.0 / 40, 1.0 / 80};
  std::vector<double> renormalised, plain;
  for (double dx : spacings) {
    renormalised.push_back(sine_mode_error(dx, "renormalised"));
    plain.push_back(sine_mode_error(dx, "plain"));
  }
  fmt::print("\nInsulated mode cos(pi x) cos(pi y), max error at t = 0.05 (amplitude 0.37)\n");
  fmt::print("  spacing   renormalised  order   plain        order\n");
  for (std::size_t k = 0; k < spacings.size(); ++k) {
    if (k == 0)
      fmt::print("  1/{:<6}  {:.3e}      -      {:.3e}    -\n", std::lround(1 / spacings[k]), renormalised[k], plain[k]);
    else
      fmt::print("  1/{:<6}  {:.3e}   {:5.2f}    {:.3e}  {:5.2f}\n", std::lround(1 / spacings[k]), renormalised[k],
                 test::observed_order(renormalised[k - 1], renormalised[k]), plain[k],
                 test::observed_order(plain[k - 1], plain[k]));
  }
  for (std::size_t k = 1; k < spacings.size(); ++k)
    CHECK(test::observed_order(renormalised[k - 1], renormalised[k]) >= 1.8);
  // The plain form does not converge at fixed h/spacing.
  CHECK(test::observed_order(plain[2], plain[3]) < 0.5);
  CHECK(plain.back() > 20.0 * renormalised.back());
}

TEST_CASE("Suddenly cooled half-space follows the erf solution", "[verification][conduction]") {
  const double t_end = 0.02;  // penetration 4 sqrt(t) = 0.57 < 1: the far end stays at Ti
  const std::vector<double> spacings{0.02, 0.01, 0.005, 0.0025};
  std::vector<double> errors;
  for (double dx : spacings) {
    auto p = test::rectangle_project(
        1.0, 2 * dx, R"({ "left": { "temperature": 0.0 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
        test::unit_soil(-100.0, 0.0), 1.0, t_end, test::numerics(dx));
    auto m = run::build_model(p);
    double error = 0.0;
    test::march(m, {t_end}, [&](std::size_t) {
      for (std::size_t i = 0; i < m.model->free_count(); ++i) {
        const double x = m.particles().position[i][0];
        error = std::max(error, std::abs(m.model->temperature()[i] - std::erf(x / (2.0 * std::sqrt(t_end)))));
      }
    });
    errors.push_back(error);
  }
  fmt::print("\nSuddenly cooled half-space, max |T - erf| at t = 0.02 (range 1)\n  spacing  error      order\n");
  for (std::size_t k = 0; k < spacings.size(); ++k)
    fmt::print("  {:<7}  {:.3e}  {}\n", spacings[k], errors[k],
               k ? fmt::format("{:.2f}", test::observed_order(errors[k - 1], errors[k])) : "-");
  for (std::size_t k = 1; k < spacings.size(); ++k) CHECK(errors[k] < errors[k - 1]);
  CHECK(errors.back() < 0.01);
}
