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

double sine_mode_error(double dx, const std::string& laplacian) {
  return test::insulated_sine_mode_error(test::numerics(dx, laplacian));
}

}  // namespace

TEST_CASE("Insulated sine mode decays as exp(-2 pi^2 t), second order", "[freezing][verification][conduction]") {
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
      fmt::print("  1/{:<6}  {:.3e}      -      {:.3e}    -\n", std::lround(1 / spacings[k]), renormalised[k],
                 plain[k]);
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

TEST_CASE("Suddenly cooled half-space follows the erf solution", "[freezing][verification][conduction]") {
  const std::vector<double> spacings{0.02, 0.01, 0.005, 0.0025};
  std::vector<double> errors;
  for (double dx : spacings) errors.push_back(test::cooled_half_space_error(dx, test::numerics(dx)));
  fmt::print("\nSuddenly cooled half-space, max |T - erf| at t = 0.02 (range 1)\n  spacing  error      order\n");
  for (std::size_t k = 0; k < spacings.size(); ++k)
    fmt::print("  {:<7}  {:.3e}  {}\n", spacings[k], errors[k],
               k ? fmt::format("{:.2f}", test::observed_order(errors[k - 1], errors[k])) : "-");
  for (std::size_t k = 1; k < spacings.size(); ++k) CHECK(errors[k] < errors[k - 1]);
  CHECK(errors.back() < 0.01);
}
