#include "pore_water/drag_law.hpp"

#include <cmath>
#include <numbers>

namespace frostwall::pore_water {

namespace {
// Re on the superficial slip (porosity x the interstitial speed).
double reynolds(const Fluid& fluid, double d, double porosity, double speed) {
  return fluid.density * porosity * speed * d / fluid.viscosity;
}
}  // namespace

double schiller_naumann_cd(double Re) { return Re < 1000.0 ? 24.0 / Re * (1.0 + 0.15 * std::pow(Re, 0.687)) : 0.44; }

Vec3 DiFeliceDrag::force(const Fluid& fluid, double d, double porosity, const Vec3& slip) const {
  const double speed = slip.norm();
  if (speed == 0.0) return Vec3::Zero();
  const double Re = reynolds(fluid, d, porosity, speed);
  const double Cd = std::pow(0.63 + 4.8 / std::sqrt(Re), 2);
  const double chi = 3.7 - 0.65 * std::exp(-0.5 * std::pow(1.5 - std::log10(Re), 2));
  const double area = 0.25 * std::numbers::pi * d * d;
  return 0.5 * Cd * fluid.density * area * porosity * porosity * std::pow(porosity, -chi) * speed * slip;
}

Vec3 SchillerNaumannDrag::force(const Fluid& fluid, double d, double porosity, const Vec3& slip) const {
  const double speed = slip.norm();
  if (speed == 0.0) return Vec3::Zero();
  const double Re = reynolds(fluid, d, porosity, speed);
  const double Cd = schiller_naumann_cd(Re);
  const double area = 0.25 * std::numbers::pi * d * d;
  return 0.5 * Cd * fluid.density * area * speed * slip;
}

}  // namespace frostwall::pore_water
