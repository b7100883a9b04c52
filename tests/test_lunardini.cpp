// Story: Lunardini's three-zone freezing (Lunardini 1981, "Heat Transfer in
// Cold Climates", 3.4): a half-space at Ti = 0.5 above a linear freezing
// range [T2, T1] = [-0.5, 0], cooled from x = 0 held at T0 = -1. The
// latent heat L = 1 is released evenly over the range, so the mushy zone is
// a conductor of capacity Cm + L / (T1 - T2) and there is no latent jump at
// either front. k = 1 in every zone; capacities 0.8 frozen, 1.2 unfrozen,
// their mean inside the range (as the linear freezing curve holds it).
// Exact answer, computed here: each zone an erf profile in x / (2 sqrt t),
// the solidus front X2 = 2 l2 sqrt(t) and the liquidus front
// X1 = 2 l1 sqrt(t) from the flux balance at both (Newton on l1, l2).
// Tolerance: both fronts within 1 % of the exact ones at the finest
// spacing, and the error falls as the spacing halves.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <fmt/core.h>

#include "support.hpp"

using namespace frostwall;

namespace {

constexpr double T0 = -1.0, T2 = -0.5, T1 = 0.0, Ti = 0.5, L = 1.0;
constexpr double C1 = 0.8, C3 = 1.2, C2 = 0.5 * (C1 + C3) + L / (T1 - T2);
constexpr double a1 = 1.0 / C1, a2 = 1.0 / C2, a3 = 1.0 / C3;  // k = 1

// Flux mismatch at the solidus and at the liquidus for fronts l2 < l1.
std::array<double, 2> mismatch(double l1, double l2) {
  const double s = std::sqrt(M_PI);
  const double mushy = std::erf(l1 / std::sqrt(a2)) - std::erf(l2 / std::sqrt(a2));
  const double frozen_out = (T2 - T0) / std::erf(l2 / std::sqrt(a1)) * std::exp(-l2 * l2 / a1) / std::sqrt(a1);
  const double mushy_at2 = (T1 - T2) / mushy * std::exp(-l2 * l2 / a2) / std::sqrt(a2);
  const double mushy_at1 = (T1 - T2) / mushy * std::exp(-l1 * l1 / a2) / std::sqrt(a2);
  const double unfrozen_in = (Ti - T1) / std::erfc(l1 / std::sqrt(a3)) * std::exp(-l1 * l1 / a3) / std::sqrt(a3);
  return {(frozen_out - mushy_at2) / s, (mushy_at1 - unfrozen_in) / s};
}

std::array<double, 2> exact_fronts() {  // {l1, l2}
  double l1 = 0.6, l2 = 0.3;
  for (int it = 0; it < 100; ++it) {
    const auto f = mismatch(l1, l2);
    const double e = 1e-7;
    const auto f1 = mismatch(l1 + e, l2), f2 = mismatch(l1, l2 + e);
    const double j11 = (f1[0] - f[0]) / e, j12 = (f2[0] - f[0]) / e, j21 = (f1[1] - f[1]) / e, j22 = (f2[1] - f[1]) / e;
    const double det = j11 * j22 - j12 * j21;
    const double d1 = (f[0] * j22 - f[1] * j12) / det, d2 = (j11 * f[1] - j21 * f[0]) / det;
    l1 -= 0.5 * d1;
    l2 -= 0.5 * d2;
    if (std::abs(d1) + std::abs(d2) < 1e-13) break;
  }
  return {l1, l2};
}

// Where the temperatures along the strip's lower row first rise through T
// (linear between particles).
double crossing(const freezing::Model& m, double T) {
  const auto& x = m.particles().position;
  const auto& temperature = m.model->temperature();
  std::vector<std::pair<double, double>> row;
  for (std::size_t i = 0; i < m.model->free_count(); ++i)
    if (x[i][1] < x[0][1] + 1e-9 || std::abs(x[i][1] - x[0][1]) < 1e-9) row.emplace_back(x[i][0], temperature[i]);
  std::sort(row.begin(), row.end());
  for (std::size_t k = 1; k < row.size(); ++k)
    if (row[k - 1].second < T && row[k].second >= T)
      return row[k - 1].first +
             (T - row[k - 1].second) / (row[k].second - row[k - 1].second) * (row[k].first - row[k - 1].first);
  return NAN;
}

// Relative errors of the liquidus and solidus fronts at t = 0.5 and 1.
std::array<double, 2> front_errors(double dx, const std::array<double, 2>& l) {
  const std::string soil = fmt::format(
      R"({{ "name": "three zones", "density": 1, "unfrozen": {{ "conductivity": 1, "heat_capacity": {} }},
          "frozen": {{ "conductivity": 1, "heat_capacity": {} }}, "latent_heat": {}, "freezing_point": {},
          "freezing_curve": {{ "model": "linear", "range": {} }} }})",
      C3, C1, L, T1, T1 - T2);
  const auto p = test::rectangle_project(
      4.0, 2 * dx,
      R"({ "left": { "temperature": -1.0 }, "right": { "temperature": 0.5 }, "top": "adiabatic", "bottom": "adiabatic" })",
      soil, Ti, 1.0, test::numerics(dx, "renormalised", "rkl2"));
  auto m = freezing::build_model(p);
  std::array<double, 2> worst{0.0, 0.0};
  test::march(m, {0.5, 1.0}, [&](std::size_t k) {
    const double t = k == 0 ? 0.5 : 1.0;
    for (int z = 0; z < 2; ++z) {
      const double exact = 2.0 * l[z] * std::sqrt(t);
      worst[z] = std::max(worst[z], std::abs(crossing(m, z == 0 ? T1 : T2) - exact) / exact);
    }
  });
  return worst;
}

}  // namespace

TEST_CASE("Lunardini's three zones: both fronts of a linear freezing range", "[freezing][verification][lunardini]") {
  const auto l = exact_fronts();
  const auto check = mismatch(l[0], l[1]);
  REQUIRE(std::abs(check[0]) + std::abs(check[1]) < 1e-10);
  REQUIRE(l[1] < l[0]);
  const auto coarse = front_errors(0.04, l), fine = front_errors(0.02, l), finest = front_errors(0.01, l);
  fmt::print(
      "\nLunardini: l1 = {:.6f}, l2 = {:.6f}; liquidus error {:.3e} {:.3e} {:.3e}, solidus {:.3e} {:.3e} {:.3e}\n",
      l[0], l[1], coarse[0], fine[0], finest[0], coarse[1], fine[1], finest[1]);
  CHECK(finest[0] < 0.01);
  CHECK(finest[1] < 0.01);
  CHECK(finest[0] < coarse[0]);
  CHECK(finest[1] < coarse[1]);
}
