// Story: a coaxial freeze pipe 30 m long (127 mm steel freeze pipe, 63 mm
// polyethylene supply pipe) carrying 1.5 m3/h of calcium chloride brine
// supplied at -30 C, in ground whose temperature at the pipe's wall is held
// at -10 C, in steady state. References:
//  - exact (Hellstrom 1991; Beier et al. 2014): with the wall's temperature
//    fixed, the two channels' balances are two coupled linear ODEs with
//    constant coefficients; their solution, two exponentials from the
//    eigenvalues of the 2 x 2 matrix, is computed here for both supply
//    channels. The outlet within 0.02 K and the profile within 0.05 K, the
//    error falling fourfold as the cells halve (second order);
//  - energy: the brine's heat gain W (T_return - T_supply) equals the heat
//    the cells draw from the wall, to round-off;
//  - the films: continuous where the turbulent blend ends (Re = 1e4), and
//    laminar values by hand (Nu = 4.364; the annulus' 3.66 + ...).
#include <catch2/catch.hpp>

#include <cmath>
#include <fmt/core.h>

#include "design/brine_circuit.hpp"

using namespace frostwall::design;

namespace {

constexpr double length = 30.0, flow = 1.5 / 3600.0, supply = -30.0, wall = -10.0;

CoaxialPipe pipe() { return {0.127, 0.0063, 50.0, 0.063, 0.0058, 0.4, length}; }
Brine brine() { return {1290.0, 0.0098, 0.52, 2700.0}; }

// The exact channel temperatures at depth z.
struct Exact {
  double l[2], v1[2], v2[2], alpha, beta;
  Exact(const CoaxialResistances& r, double W, SupplyChannel s) {
    const double g = 1.0 / r.ground, k = 1.0 / r.channels;
    const double gd = s == SupplyChannel::annulus ? g : 0.0, gu = g - gd;
    // y' = A y, A = [[-(gd+k), k], [-k, gu+k]] / W, y = T - T_wall.
    const double tr = (gu - gd) / W, det = (-(gd + k) * (gu + k) + k * k) / (W * W);
    const double root = std::sqrt(tr * tr - 4 * det);
    l[0] = 0.5 * (tr - root), l[1] = 0.5 * (tr + root);
    for (int i = 0; i < 2; ++i) v1[i] = k / W, v2[i] = (gd + k) / W + l[i];
    // y_d(0) = supply - wall; y_u(L) = y_d(L).
    const double a11 = v1[0], a12 = v1[1], b1 = supply - wall;
    const double a21 = (v2[0] - v1[0]) * std::exp(l[0] * length), a22 = (v2[1] - v1[1]) * std::exp(l[1] * length);
    alpha = b1 * a22 / (a11 * a22 - a12 * a21);
    beta = -b1 * a21 / (a11 * a22 - a12 * a21);
  }
  double down(double z) const { return wall + alpha * v1[0] * std::exp(l[0] * z) + beta * v1[1] * std::exp(l[1] * z); }
  double up(double z) const { return wall + alpha * v2[0] * std::exp(l[0] * z) + beta * v2[1] * std::exp(l[1] * z); }
};

struct Errors {
  double outlet, profile;
};

Errors errors(SupplyChannel s, int cells) {
  const auto r = coaxial_resistances(pipe(), brine(), flow);
  const double W = brine().density * brine().heat_capacity * flow;
  const auto p = steady_brine(length, cells, r, W, s, supply, [](double) { return wall; });
  const Exact e(r, W, s);
  Errors out{std::abs(p.return_temperature - e.up(0.0)), 0.0};
  for (int i = 0; i <= cells; ++i)
    out.profile =
        std::max({out.profile, std::abs(p.down[i] - e.down(p.depth[i])), std::abs(p.up[i] - e.up(p.depth[i]))});
  double drawn = 0.0;
  for (double q : p.draw) drawn += q * length / cells;
  CHECK(p.heat == Approx(drawn).epsilon(1e-12));
  CHECK(p.heat > 0.0);
  return out;
}

}  // namespace

TEST_CASE("A coaxial freeze pipe in steady state against the exact two-channel solution", "[design][brine][coaxial]") {
  for (auto s : {SupplyChannel::annulus, SupplyChannel::inner}) {
    const auto coarse = errors(s, 15), fine = errors(s, 30), finest = errors(s, 60);
    const auto r = coaxial_resistances(pipe(), brine(), flow);
    const double W = brine().density * brine().heat_capacity * flow;
    const Exact e(r, W, s);
    fmt::print("\nCoaxial pipe, supply down the {}: return {:.4f} C (exact), R_channels {:.4f}, R_ground {:.4f} m K/W; "
               "outlet error {:.2e} / {:.2e} / {:.2e} K, profile {:.2e} / {:.2e} / {:.2e} K at 15 / 30 / 60 cells\n",
               s == SupplyChannel::annulus ? "annulus" : "inner pipe", e.up(0.0), r.channels, r.ground, coarse.outlet,
               fine.outlet, finest.outlet, coarse.profile, fine.profile, finest.profile);
    CHECK(fine.outlet < 0.02);
    CHECK(fine.profile < 0.05);
    CHECK(finest.profile < 0.3 * fine.profile);  // second order: a quarter
    CHECK(fine.profile < 0.3 * coarse.profile);
  }
}

TEST_CASE("Freeze pipe films: laminar by hand, continuous where turbulence begins", "[design][brine][coaxial]") {
  const auto r = coaxial_resistances(pipe(), brine(), flow);
  // 1.5 m3/h of brine at 9.8 mPa s: laminar in both channels.
  CHECK(r.inner.reynolds < 2300);
  CHECK(r.annulus.reynolds < 2300);
  CHECK(r.inner.nusselt == 4.364);
  const double a = 0.063 / (0.127 - 2 * 0.0063);
  CHECK(r.annulus.nusselt == Approx(3.66 + (4 - 0.102 / (a + 0.02)) * std::pow(a, 0.04)).epsilon(1e-12));
  // The blend meets the turbulent formula at Re = 1e4 (Konakov's xi there is 0.0309).
  for (double Pr : {7.0, 50.0}) {
    CHECK(pipe_nusselt(1e4 - 1e-6, Pr, 0.0) == Approx(pipe_nusselt(1e4, Pr, 0.0)).epsilon(5e-3));
    CHECK(annulus_nusselt(1e4 - 1e-6, Pr, 0.5, 0.0) == Approx(annulus_nusselt(1e4, Pr, 0.5, 0.0)).epsilon(5e-3));
  }
  CHECK(pipe_nusselt(5e4, 7.0, 0.0) > pipe_nusselt(2e4, 7.0, 0.0));
}

TEST_CASE("The brine driven by the heat the ground draws reproduces the brine driven by the wall",
          "[design][brine][coaxial]") {
  // The same pipe: the wall's solution gives each cell's draw; handed back
  // as the draw, it must give the same temperatures, and the brine's gain
  // must be the draw's sum.
  const auto r = coaxial_resistances(pipe(), brine(), flow);
  const double W = brine().density * brine().heat_capacity * flow;
  for (auto s : {SupplyChannel::annulus, SupplyChannel::inner}) {
    const int cells = 40;
    const auto by_wall = steady_brine(length, cells, r, W, s, supply, [](double z) { return wall + 0.2 * z; });
    const auto by_draw = brine_with_draw(length, cells, r, W, s, supply, [&](double z) {
      return by_wall.draw[std::min(cells - 1, static_cast<int>(z / (length / cells)))];
    });
    for (int i = 0; i <= cells; ++i) {
      CHECK(by_draw.down[i] == Approx(by_wall.down[i]).margin(1e-9));
      CHECK(by_draw.up[i] == Approx(by_wall.up[i]).margin(1e-9));
    }
    double drawn = 0.0;
    for (double q : by_draw.draw) drawn += q * length / cells;
    CHECK(by_draw.heat == Approx(drawn).epsilon(1e-12));
  }
}
