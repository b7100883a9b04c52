// The "no closure" verdict against hand values: a frozen area
// that saturates as 1 - exp(-t / tau) enters the 1 % band of its last
// value where exp(-t/tau) - exp(-T/tau) = 0.01 (1 - exp(-T/tau)); one that
// grows linearly never does.
#include <catch2/catch.hpp>
#include <cmath>

#include "post/frozen_area_trend.hpp"

using frostwall::post::FrozenAreaTrend;

TEST_CASE("Frozen area trend: a saturating area is steady from the band's day, a growing one is not",
          "[freezing][groundwater][post]") {
  const double tau = 5.0, T = 60.0;
  FrozenAreaTrend saturating, growing;
  for (int k = 0; k <= 6000; ++k) {
    const double t = T * k / 6000.0;
    saturating.add(t, 1.0 - std::exp(-t / tau));
    growing.add(t, 0.1 + 0.01 * t);
  }
  const double last = 1.0 - std::exp(-T / tau);
  const double exact = -tau * std::log(0.01 * last + std::exp(-T / tau));
  REQUIRE(saturating.steady_since().has_value());
  CHECK(*saturating.steady_since() == Approx(exact).epsilon(1e-4));
  CHECK(saturating.no_closure_verdict() == "no closure: the frozen area stopped growing (steady state) by day 24");
  CHECK_FALSE(growing.steady_since().has_value());
  // The last fifth's growth: 0.01 per day over an area of 0.7.
  CHECK(growing.recent_growth_per_day() == Approx(0.01 / 0.7).epsilon(1e-9));
  CHECK(growing.no_closure_verdict() == "no closure by day 60: the frozen area still grows by 1.4 % a day");
}
