// Story: a soil whose water freezes along a smooth curve, InterFrost's
// exponential S_w = 0.05 + 0.95 exp(-(T/0.5)^2) and an Anderson-Tice power
// law w_u = 0.05 theta^-0.5. Reference: the curve itself and the heat it
// holds, integrated here independently (Simpson's rule on 200 000 steps):
//   H(T2) - H(T1) = int (rho Cs + f (rho Cl - rho Cs)) dT + rho L (f(T2) - f(T1)),
// the liquid fraction at a temperature is the curve's, temperature and
// enthalpy invert each other, and ground counts as frozen where half the
// water is ice. Bad curves name their path.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <string>

#include "project/project.hpp"
#include "soil_text.hpp"
#include "thermal/phase_change.hpp"

using namespace frostwall;

namespace {

const std::string th2 = testing::th2_constituents + ", ";
using testing::soil_of;

double simpson(const std::function<double(double)>& g, double a, double b) {
  const int n = 200000;
  const double h = (b - a) / n;
  double s = g(a) + g(b);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * g(a + k * h);
  return s * h / 3.0;
}

// Checks the law against curve f (degC -> liquid share) between T_lo and T_hi.
void check_law(const project::Soil& soil, const std::function<double(double)>& f, double T_lo, double T_hi) {
  const thermal::PhaseChangeLaw law(soil);
  REQUIRE(law.tabulated());
  const double cs = soil.density * soil.frozen.heat_capacity, cl = soil.density * soil.unfrozen.heat_capacity;
  const double rhoL = soil.density * soil.latent_heat;
  auto sensible = [&](double T) { return cs + f(T) * (cl - cs); };
  double worst_H = 0.0, worst_T = 0.0, worst_f = 0.0;
  const double H_lo = law.enthalpy(T_lo);
  for (int k = 1; k <= 40; ++k) {
    const double T = T_lo + (T_hi - T_lo) * k / 40.0;
    const double exact = simpson(sensible, T_lo, T) + rhoL * (f(T) - f(T_lo));
    worst_H = std::max(worst_H, std::abs(law.enthalpy(T) - H_lo - exact) / rhoL);
    worst_T = std::max(worst_T, std::abs(law.temperature(law.enthalpy(T)) - T));
    worst_f = std::max(worst_f, std::abs(law.liquid_fraction(law.enthalpy(T)) - f(T)));
  }
  INFO("heat " << worst_H << " of rho L, temperature " << worst_T << " K, liquid share " << worst_f);
  CHECK(worst_H < 1e-5);
  CHECK(worst_T < 1e-4);
  CHECK(worst_f < 1e-4);
  // Frozen where half the water is ice.
  const double T_half = law.frozen_temperature();
  CHECK(f(T_half) == Approx(0.5).margin(1e-4));
  CHECK(law.latent_left(law.enthalpy(T_half)) == Approx(0.0).margin(1e-6));
  CHECK(law.latent_left(law.latent_enthalpy()) == Approx(1.0).margin(1e-12));
  // The slope on either side of a point is the local dT/dH.
  const double T = 0.5 * (T_lo + T_half), H = law.enthalpy(T), dH = 1e-3 * rhoL;
  CHECK(law.temperature_slope(H, 1.0) ==
        Approx((law.temperature(H + dH) - law.temperature(H - dH)) / (2 * dH)).epsilon(0.02));
}

}  // namespace

TEST_CASE("The exponential freezing curve holds the heat its curve says", "[freezing_curve]") {
  const auto soil = soil_of(th2 + R"("freezing_curve": { "model": "exponential", "width": 0.5,
      "residual_saturation": 0.05 } })");
  REQUIRE(soil.freezing_curve.model == project::CurveModel::exponential);
  auto f = [](double T) { return T >= 0.0 ? 1.0 : 0.05 + 0.95 * std::exp(-(T / 0.5) * (T / 0.5)); };
  check_law(soil, f, -1.8, 3.0);
  const thermal::PhaseChangeLaw law(soil);
  CHECK(law.frozen_temperature() == Approx(-0.5 * std::sqrt(std::log(0.95 / 0.45))).margin(1e-4));
  // Colder than the table, the residual water stays liquid.
  CHECK(law.liquid_fraction(law.enthalpy(-10.0)) == Approx(0.05).margin(1e-6));
}

TEST_CASE("The power freezing curve begins where the unfrozen water content reaches the total", "[freezing_curve]") {
  // w = 0.37 * 1000 / (0.63 * 2650) = 0.2216...; onset theta* = (w / 0.05)^(1 / -0.5).
  const auto soil = soil_of(th2 + R"("freezing_curve": { "model": "power", "alpha": 0.05, "beta": -0.5 } })");
  const double w = 0.37 * 1000 / (0.63 * 2650), onset = -std::pow(w / 0.05, -2.0);
  REQUIRE(soil.freezing_curve.water_content == Approx(w).epsilon(1e-12));
  auto f = [&](double T) { return T >= onset ? 1.0 : std::min(1.0, 0.05 * std::pow(-T, -0.5) / w); };
  check_law(soil, f, -30.0, 2.0);
  const thermal::PhaseChangeLaw law(soil);
  CHECK(law.freezing_point() == Approx(onset).epsilon(1e-12));
}

TEST_CASE("Bad freezing curves are named by path", "[freezing_curve]") {
  for (const auto& [curve, path] : std::vector<std::pair<std::string, std::string>>{
           {R"({ "model": "exponential", "width": 0.5, "residual_saturation": 0.6 })",
            "soil.freezing_curve.residual_saturation: must be below 0.5"},
           {R"({ "model": "exponential" })", "soil.freezing_curve.width: required"},
           {R"({ "model": "power", "alpha": 0.05, "beta": 0.5 })", "soil.freezing_curve.beta: must be negative"},
           {R"({ "model": "power", "alpha": 5, "beta": -0.1 })", "soil.freezing_curve: keeps half its water liquid"},
           {R"({ "model": "step", "width": 1 })", "soil.freezing_curve.width: not a field of the step curve"},
           {R"({ "model": "cubic" })", "soil.freezing_curve.model:"}}) {
    try {
      soil_of(th2 + R"("freezing_curve": )" + curve + "}");
      FAIL("accepted " << curve);
    } catch (const project::ProjectError& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(path) != std::string::npos);
    }
  }
  try {  // the old soil needs the power law's water content
    soil_of(R"("sand")");
    soil_of(R"({ "density": 2000, "unfrozen": { "conductivity": 2, "heat_capacity": 1500 },
        "frozen": { "conductivity": 2.5, "heat_capacity": 1100 }, "latent_heat": 50000,
        "freezing_curve": { "model": "power", "alpha": 0.05, "beta": -0.5 } })");
    FAIL("the power curve without a water content was accepted");
  } catch (const project::ProjectError& e) {
    CHECK(std::string(e.what()).find("soil.freezing_curve.water_content: required") != std::string::npos);
  }
}
