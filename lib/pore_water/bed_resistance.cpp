#include "pore_water/bed_resistance.hpp"

#include <cmath>
#include <numbers>

namespace frostwall::pore_water {

double ergun_gradient(const Fluid& fluid, double e, double d, double U) {
  const double s = 1.0 - e, e3 = e * e * e;
  return 150.0 * fluid.viscosity * s * s * U / (e3 * d * d) + 1.75 * fluid.density * s * std::abs(U) * U / (e3 * d);
}

double ergun_velocity(const Fluid& fluid, double e, double d, double gradient) {
  double lo = 0.0, hi = 100.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (ergun_gradient(fluid, e, d, mid) < gradient ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double wen_yu_gradient(const Fluid& fluid, double e, double d, double U) {
  if (U == 0.0) return 0.0;
  const double Re = fluid.density * std::abs(U) * d / fluid.viscosity;
  const double Cd = schiller_naumann_cd(Re);
  return 0.75 * Cd * fluid.density * (1.0 - e) * std::abs(U) * U * std::pow(e, -2.65) / (e * e * d);
}

namespace {
double blend(double e) { return 0.5 + std::atan(262.5 * ((1.0 - e) - 0.2)) / std::numbers::pi; }
}  // namespace

double bed_gradient(const Fluid& fluid, double e, double d, double U) {
  const double phi = blend(e);
  return phi * ergun_gradient(fluid, e, d, U) + (1.0 - phi) * wen_yu_gradient(fluid, e, d, U);
}

double bed_gradient_per_solid(const Fluid& fluid, double e, double d, double U) {
  const double phi = blend(e), e3 = e * e * e;
  const double ergun = 150.0 * fluid.viscosity * (1.0 - e) * U / (e3 * d * d) +
                       1.75 * fluid.density * std::abs(U) * U / (e3 * d);
  double wen_yu = 0.0;
  if (U != 0.0) {
    const double Re = fluid.density * std::abs(U) * d / fluid.viscosity;
    wen_yu = 0.75 * schiller_naumann_cd(Re) * fluid.density * std::abs(U) * U * std::pow(e, -2.65) / (e * e * d);
  }
  return phi * ergun + (1.0 - phi) * wen_yu;
}

}  // namespace frostwall::pore_water
