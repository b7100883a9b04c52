#include "freezing/design_check.hpp"

#include <cmath>
#include "design/wall_strength.hpp"

namespace frostwall::freezing {

WallCheck check_wall(const project::Design& d, double a, double min_thickness, std::optional<double> mean_temperature) {
  WallCheck check;
  for (design::Formula f : design::all_formulas) check.required_by[std::string(design::name(f))] = nullptr;
  if (!d.checks_strength() || !mean_temperature) return check;
  const double s = d.allowable_factor * d.strength->at(*mean_temperature);
  check.allowable = s;
  if (s <= 0.0) return check;
  // Mohr-Coulomb's cohesion from the same allowable strength: sigma_c =
  // 2 c cos phi / (1 - sin phi) = s, so the two plastic limits meet at phi = 0.
  std::optional<design::MohrCoulomb> mc;
  if (d.friction_angle) {
    const double phi = *d.friction_angle * M_PI / 180.0;
    mc = design::MohrCoulomb{s * (1.0 - std::sin(phi)) / (2.0 * std::cos(phi)), *d.friction_angle};
  }
  for (design::Formula f : design::all_formulas) {
    const auto E = design::required_thickness(f, a, *d.pressure, s, mc ? &*mc : nullptr);
    check.required_by[std::string(design::name(f))] = E ? nlohmann::json(*E) : nlohmann::json(nullptr);
    if (f == d.formula) check.required = E;
  }
  if (check.required && min_thickness > 0.0) check.utilisation = *check.required / min_thickness;
  return check;
}

DesignMet design_met(const std::vector<double>& days, const std::vector<WallCheck>& checks) {
  DesignMet met;
  for (std::size_t k = 0; k < checks.size(); ++k) {
    const bool ok = checks[k].utilisation && *checks[k].utilisation <= 1.0;
    if (ok && !met.day) met.day = days[k], met.stays = true;
    if (!ok && met.day) met.stays = false;
  }
  return met;
}

}  // namespace frostwall::freezing
