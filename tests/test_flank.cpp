// A bump's flanks (post/flank.hpp) against hand calculations: a cone-shaped
// profile sampled on a grid has straight flanks whose 10 % and 90 % points,
// slope and foot follow from its apex and base; a profile that ends before
// falling through 10 % has no flank on that side.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "post/flank.hpp"

using frostwall::post::bump_flanks;

namespace {

// A triangle: height h at x0, falling to 0 at x0 - a and x0 + b, zero beyond.
std::vector<double> triangle(const std::vector<double>& x, double x0, double h, double a, double b) {
  std::vector<double> f;
  for (double xi : x) {
    const double v = xi < x0 ? h * (1.0 - (x0 - xi) / a) : h * (1.0 - (xi - x0) / b);
    f.push_back(std::max(0.0, v));
  }
  return f;
}

double degrees(double rise, double run) { return std::atan2(rise, run) * 180.0 / std::numbers::pi; }

}  // namespace

TEST_CASE("Flank: a triangular bump's slopes, feet and width are its own", "[post][flank]") {
  std::vector<double> x;
  for (int i = 0; i <= 200; ++i) x.push_back(0.001 * i);  // 0 .. 0.2 m
  const double h = 0.03, x0 = 0.1, a = 0.05, b = 0.08;    // flanks rise h over a and over b
  const auto bump = bump_flanks(x, triangle(x, x0, h, a, b));
  CHECK(bump.peak == Approx(h));
  CHECK(bump.peak_x == Approx(x0));
  REQUIRE(bump.low_side);
  REQUIRE(bump.high_side);
  // Linear interpolation between samples of a straight line is exact.
  CHECK(bump.low_side->x90 == Approx(x0 - 0.1 * a).margin(1e-12));
  CHECK(bump.low_side->x10 == Approx(x0 - 0.9 * a).margin(1e-12));
  CHECK(bump.high_side->x10 == Approx(x0 + 0.9 * b).margin(1e-12));
  CHECK(bump.low_side->slope_deg == Approx(degrees(h, a)).epsilon(1e-9));
  CHECK(bump.high_side->slope_deg == Approx(degrees(h, b)).epsilon(1e-9));
  CHECK(bump.low_side->foot == Approx(x0 - a).margin(1e-12));
  CHECK(bump.high_side->foot == Approx(x0 + b).margin(1e-12));
  CHECK(*bump.width() == Approx(a + b).margin(1e-12));
  CHECK(*bump.mean_slope_deg() == Approx(0.5 * (degrees(h, a) + degrees(h, b))).epsilon(1e-9));
  // Raised by a constant (ground that settled everywhere): measured from the base, nothing else changes.
  auto raised = triangle(x, x0, h, a, b);
  for (double& v : raised) v += 0.007;
  const auto lifted = bump_flanks(x, raised);
  CHECK(lifted.base == Approx(0.007));
  CHECK(lifted.peak == Approx(h));
  CHECK(lifted.low_side->slope_deg == Approx(bump.low_side->slope_deg).epsilon(1e-9));
  CHECK(*lifted.width() == Approx(a + b).margin(1e-12));
}

TEST_CASE("Flank: a bump cut off by the profile's end has one flank and a flat profile none", "[post][flank]") {
  std::vector<double> x;
  for (int i = 0; i <= 100; ++i) x.push_back(0.001 * i);
  // The apex at 0.02 with a 0.05 base each side: the low side ends at 10 % ... 60 % of the height.
  const auto cut = bump_flanks(x, triangle(x, 0.02, 0.01, 0.05, 0.05));
  CHECK_FALSE(cut.low_side);
  REQUIRE(cut.high_side);
  CHECK_FALSE(cut.width());
  CHECK(*cut.mean_slope_deg() == Approx(cut.high_side->slope_deg));
  const auto flat = bump_flanks(x, std::vector<double>(x.size(), 0.0));
  CHECK(flat.peak == 0.0);
  CHECK_FALSE(flat.low_side);
  CHECK_FALSE(flat.mean_slope_deg());
}
