#include "design/wall_strength.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <stdexcept>

namespace frostwall::design {

std::optional<double> required_thickness(Formula f, double a, double P, double s, const MohrCoulomb* mc) {
  if (a <= 0.0 || P < 0.0 || s <= 0.0) throw std::invalid_argument("required_thickness: a, s > 0 and P >= 0 expected");
  const double ratio = P / s;
  switch (f) {
    case Formula::lame_tresca:
      if (s <= 2.0 * P) return std::nullopt;
      return a * (std::sqrt(s / (s - 2.0 * P)) - 1.0);
    case Formula::lame_mises:
      if (s <= std::sqrt(3.0) * P) return std::nullopt;
      return a * (std::sqrt(s / (s - std::sqrt(3.0) * P)) - 1.0);
    case Formula::domke: return a * (0.29 * ratio + 2.3 * ratio * ratio);
    case Formula::plastic_tresca: return a * std::expm1(ratio);
    case Formula::plastic_mohr_coulomb: {
      if (!mc || mc->cohesion <= 0.0) return std::nullopt;
      const double sin_phi = std::sin(mc->friction_angle * M_PI / 180.0);
      const double N = (1.0 + sin_phi) / (1.0 - sin_phi);
      const double sigma_c = 2.0 * mc->cohesion * std::cos(mc->friction_angle * M_PI / 180.0) / (1.0 - sin_phi);
      if (N - 1.0 < 1e-12) return a * std::expm1(P / sigma_c);  // phi = 0: Tresca with s = 2 c
      return a * std::expm1(std::log1p((N - 1.0) * P / sigma_c) / (N - 1.0));
    }
  }
  return std::nullopt;
}

}  // namespace frostwall::design
