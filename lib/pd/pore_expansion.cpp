#include "pd/pore_expansion.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::pd {

PoreExpansion::PoreExpansion(const project::FreezingExpansion& expansion, double matrix_modulus,
                             std::vector<project::Pore> pores, std::vector<int> pore_of)
    : expansion_(expansion),
      ice_ratio_(expansion.ice_elastic_modulus / matrix_modulus),
      pores_(std::move(pores)),
      pore_of_(std::move(pore_of)) {}

double PoreExpansion::free_strain(double phi) const {
  return std::sqrt(1.0 + expansion_.volume_change * std::clamp(phi, 0.0, 1.0)) - 1.0;
}

std::vector<double> PoreExpansion::frozen_fraction(const std::vector<double>& f, const std::vector<double>& volume) const {
  std::vector<double> ice(pores_.size(), 0.0), all(pores_.size(), 0.0);
  for (std::size_t i = 0; i < pore_of_.size(); ++i)
    if (pore_of_[i] >= 0) {
      ice[pore_of_[i]] += volume[i] * (1.0 - f[i]);
      all[pore_of_[i]] += volume[i];
    }
  for (std::size_t p = 0; p < ice.size(); ++p) ice[p] = all[p] > 0.0 ? ice[p] / all[p] : 0.0;
  return ice;
}

void PoreExpansion::prepare(PdSolid& solid) const {
  if (rim_displacement()) {
    std::vector<std::uint8_t> held(pore_of_.size(), 0);
    for (std::size_t i = 0; i < held.size(); ++i) held[i] = pore_of_[i] >= 0;
    solid.set_held(std::move(held));
  }
}

void PoreExpansion::apply(PdSolid& solid, const std::vector<double>& f, const std::vector<double>& volume,
                          std::vector<double>& u) const {
  const auto& x = solid.position();
  if (rim_displacement()) {
    const std::vector<double> F = frozen_fraction(f, volume);
    for (std::size_t i = 0; i < pore_of_.size(); ++i) {
      if (pore_of_[i] < 0) continue;
      const auto& pore = pores_[pore_of_[i]];
      const double R = pore.radius, ua = R * free_strain(F[pore_of_[i]]);
      const double dx = x[i][0] - pore.x, dy = x[i][1] - pore.y, r = std::hypot(dx, dy);
      // u_a R / r, radial; held at u_a R / (R/2) towards the centre (no
      // bond from the matrix reaches that deep unless the pore is tiny).
      const double ur = r > 0.0 ? ua * R / std::max(r, 0.5 * R) : 0.0;
      u[2 * i] = r > 0.0 ? ur * dx / r : 0.0;
      u[2 * i + 1] = r > 0.0 ? ur * dy / r : 0.0;
    }
    return;
  }
  std::vector<double> ratio(pore_of_.size(), 1.0), eigen(pore_of_.size(), 0.0);
  for (std::size_t i = 0; i < pore_of_.size(); ++i)
    if (pore_of_[i] >= 0) {
      const double phi = 1.0 - f[i];
      ratio[i] = ice_ratio_ * phi;
      eigen[i] = free_strain(phi);
    }
  solid.set_stiffness_ratio(ratio);
  solid.set_eigenstrain(eigen);
}

}  // namespace frostwall::pd
