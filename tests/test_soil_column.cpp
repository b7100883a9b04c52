// Story: the silty-clay column of the SPH paper, section 2.2: 0.20 m high,
// sides adiabatic, top held at -5 C, bottom at +1 C, initially +1 C;
// Tf = -0.25 C. At steady state the frozen front sits where the conductive
// fluxes balance, ks (Tf - Ttop) / X = kl (Tbot - Tf) / (0.20 - X), which
// gives X = 0.1539 m from the top (a hand calculation, done below).
// Tolerance 2 % (the acceptance tolerance); the front depth error of the
// lattice scheme is a fraction of the spacing (2.5 mm = 1.6 %... of X is
// the worst case, and it sits well inside).
// The paper reports the front settling after about 35 h; we report ours.
#include <catch2/catch.hpp>

#include "post/front.hpp"
#include "support.hpp"

using namespace frostwall;

TEST_CASE("Soil column: steady frozen front at the flux-balance depth", "[freezing][verification][soil_column]") {
  const auto soil = *project::builtin_soil("silty_clay");
  const double Ttop = -5.0, Tbot = 1.0, Hc = 0.20;
  const double ks = soil.frozen.conductivity[0], kl = soil.unfrozen.conductivity[0], Tf = soil.freezing_point;
  const double X_exact = ks * (Tf - Ttop) * Hc / (ks * (Tf - Ttop) + kl * (Tbot - Tf));
  CHECK(X_exact == Approx(0.1539).margin(5e-5));

  const double dx = 0.0025;
  const double hours = 3600.0, t_end = 72 * hours;
  // A column four particles wide: the sides are mirrors, the problem is 1-D.
  const auto p = test::rectangle_project(
      4 * dx, Hc,
      R"({ "left": "adiabatic", "right": "adiabatic", "top": { "temperature": -5 }, "bottom": { "temperature": 1 } })",
      R"("silty_clay")", 1.0, t_end, test::numerics(dx));
  auto m = freezing::build_model(p);
  REQUIRE(m.face->side == "top");
  std::vector<double> times;
  for (int k = 1; k <= 144; ++k) times.push_back(k * 0.5 * hours);
  std::vector<double> depth;
  test::march(m, times, [&](std::size_t) {
    const auto X =
        post::frozen_front(m.particles().position, m.model->liquid_fraction(), m.model->free_count(), *m.face);
    depth.push_back(X.value_or(Hc));
  });
  const double X_end = depth.back();
  // Settled: from then on within 1 % of the final depth.
  std::size_t settled = depth.size() - 1;
  while (settled > 0 && std::abs(depth[settled - 1] - X_end) <= 0.01 * X_end) --settled;
  fmt::print("\nSoil column (spacing {} m): front depth at 72 h {:.4f} m (exact steady {:.4f} m, error {:.2f} %);\n"
             "  within 1 % of it from {:.1f} h on (the paper: settles after about 35 h); depth at 12/24/36/48 h: "
             "{:.4f} {:.4f} {:.4f} {:.4f} m\n",
             dx, X_end, X_exact, 100 * (X_end - X_exact) / X_exact, times[settled] / hours, depth[23], depth[47],
             depth[71], depth[95]);
  CHECK(std::abs(X_end - X_exact) < 0.02 * X_exact);
  // Steady: the last 12 hours move the front by less than 0.1 %.
  CHECK(std::abs(depth.back() - depth[depth.size() - 25]) < 1e-3 * X_end);
}
