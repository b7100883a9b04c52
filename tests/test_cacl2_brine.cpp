// The built-in calcium chloride brine (Melinder's fit) against what it was
// not built from:
//  - at no salt, pure water at 20 C (density 998.2 kg/m3, heat capacity
//    4182 J/(kg K), conductivity 0.598 W/(m K), viscosity 1.002 mPa s) and
//    its freezing point, 0 C;
//  - VDI's Heat Atlas (Preisegger 2010, D4) at 29.9 % by mass, -30, -10 and
//    0 C: density 1309 / 1298 / 1293, heat capacity 2659 / 2700 / 2738,
//    conductivity 0.488 / 0.515 / 0.528; viscosity 22.6 / 9.0 / 5.7 mPa s,
//    where the two sources part (Melinder's is 22 % lower at -30 C);
//  - Melinder's own table (SecCool) at 29.4 %, -40 C: 1301.01 kg/m3,
//    2643.4 J/(kg K), 0.47786 W/(m K), 29.6 mPa s.
// And the freezing point falls as salt is added, below -40 C by 29 %.
#include <catch2/catch.hpp>

#include "project/cacl2_brine.hpp"

using frostwall::project::cacl2_brine;
using frostwall::project::cacl2_freezing_point;

TEST_CASE("Calcium chloride brine: water at no salt, VDI's and Melinder's tables at 29-30 %", "[plant][brine]") {
  const auto water = cacl2_brine(0.0, 20.0);
  CHECK(water.density == Approx(998.2).epsilon(0.005));
  CHECK(water.heat_capacity == Approx(4182.0).epsilon(0.01));
  CHECK(water.conductivity == Approx(0.598).epsilon(0.02));
  CHECK(water.viscosity == Approx(1.002e-3).epsilon(0.05));
  CHECK(std::abs(cacl2_freezing_point(0.0)) < 0.5);

  const double T[] = {-30.0, -10.0, 0.0};
  const double rho[] = {1309, 1298, 1293}, cp[] = {2659, 2700, 2738}, k[] = {0.488, 0.515, 0.528},
               mu[] = {22.6e-3, 9.0e-3, 5.7e-3};
  for (int i = 0; i < 3; ++i) {
    INFO("VDI at 29.9 %, " << T[i] << " C");
    const auto b = cacl2_brine(0.299, T[i]);
    CHECK(b.density == Approx(rho[i]).epsilon(0.006));
    CHECK(b.heat_capacity == Approx(cp[i]).epsilon(0.01));
    CHECK(b.conductivity == Approx(k[i]).epsilon(0.01));
    CHECK(b.viscosity == Approx(mu[i]).epsilon(0.3));
  }
  const auto cold = cacl2_brine(0.294, -40.0);
  CHECK(cold.density == Approx(1301.01).epsilon(1e-3));
  CHECK(cold.heat_capacity == Approx(2643.4).epsilon(3e-3));
  CHECK(cold.conductivity == Approx(0.47786).epsilon(3e-3));
  CHECK(cold.viscosity == Approx(29.6e-3).epsilon(0.02));

  double before = cacl2_freezing_point(0.0);
  for (double x = 0.02; x <= 0.3001; x += 0.02) {
    const double Tf = cacl2_freezing_point(x);
    CHECK(Tf < before);
    before = Tf;
  }
  CHECK(cacl2_freezing_point(0.29) < -40.0);
}
