#include "pd/pore_expansion.hpp"

#include "geometry/pores.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::pd {

PoreExpansion::PoreExpansion(const project::FreezingExpansion& expansion, double matrix_modulus,
                             std::vector<project::Pore> pores, std::vector<int> pore_of)
    : expansion_(expansion),
      ice_ratio_(expansion.ice_elastic_modulus / matrix_modulus),
      pores_(std::move(pores)),
      pore_of_(std::move(pore_of)) {}

double pore_excess(double volume_change, double saturation, double phi) {
  return std::max(saturation * volume_change * std::clamp(phi, 0.0, 1.0) - (1.0 - saturation), 0.0);
}

double PoreExpansion::free_strain(double phi, double saturation) const {
  return std::sqrt(1.0 + pore_excess(expansion_.volume_change, saturation, phi)) - 1.0;
}

std::vector<double> PoreExpansion::frozen_fraction(const std::vector<double>& f,
                                                   const std::vector<double>& volume) const {
  return geometry::pore_frozen_fraction(pore_of_, pores_.size(), f, volume);
}

void PoreExpansion::shape(const PdSolid& solid, const std::vector<double>& dT, std::vector<double>& u) {
  if (!rim_displacement()) return;
  const auto& x = solid.position();
  const double kT = solid.law().thermal_stretch_per_K;
  std::vector<double> dT_mean(pores_.size(), 0.0), count(pores_.size(), 0.0);
  for (std::size_t i = 0; i < pore_of_.size(); ++i)
    if (pore_of_[i] >= 0) {
      dT_mean[pore_of_[i]] += dT[i];
      count[pore_of_[i]] += 1.0;
    }
  shape_.resize(u.size(), 0.0);
  for (std::size_t i = 0; i < pore_of_.size(); ++i) {
    const int p = pore_of_[i];
    if (p < 0) continue;
    const auto& pore = pores_[p];
    const double R = pore.radius, ua = rim_u_.empty() ? 0.0 : rim_u_[p];
    const Vec2 d = x[i] - Vec2(pore.x, pore.y);
    const double r = d.norm();
    // u_a R / r, radial; u_a R / (R/2) towards the centre (no bond from
    // the matrix reaches that deep unless the pore is tiny).
    const Vec2 radial = r > 0.0 ? Vec2(d * (ua * R / std::max(r, 0.5 * R) / r)) : Vec2(Vec2::Zero());
    const Vec2 w = kT * (dT_mean[p] / std::max(count[p], 1.0)) * d + radial;
    // The pore keeps its translation (u - the old shape) and takes the new shape.
    for (int k = 0; k < 2; ++k) {
      u[2 * i + k] += w[k] - shape_[2 * i + k];
      shape_[2 * i + k] = w[k];
    }
  }
}

void PoreExpansion::prepare(PdSolid& solid) {
  if (rim_displacement()) {
    std::vector<std::uint8_t> held(pore_of_.size(), 0);
    std::vector<std::vector<std::size_t>> groups(pores_.size());
    for (std::size_t i = 0; i < held.size(); ++i)
      if (pore_of_[i] >= 0) {
        held[i] = 1;
        groups[pore_of_[i]].push_back(i);
      }
    solid.set_held(std::move(held));
    solid.set_groups(std::move(groups));
  }
}

void PoreExpansion::apply(PdSolid& solid, const std::vector<double>& f, const std::vector<double>& volume) {
  if (rim_displacement()) {
    const std::vector<double> F = frozen_fraction(f, volume);
    rim_u_.resize(pores_.size());
    for (std::size_t p = 0; p < pores_.size(); ++p)
      rim_u_[p] = pores_[p].radius * free_strain(F[p], pores_[p].saturation);
    // A pore is a hole until it starts to freeze, then the loading device.
    std::vector<double> ratio(pore_of_.size(), 1.0);
    for (std::size_t i = 0; i < pore_of_.size(); ++i)
      if (pore_of_[i] >= 0 && F[pore_of_[i]] <= 0.0) ratio[i] = 0.0;
    solid.set_stiffness_ratio(ratio);
    return;
  }
  std::vector<double> ratio(pore_of_.size(), 1.0), eigen(pore_of_.size(), 0.0);
  for (std::size_t i = 0; i < pore_of_.size(); ++i)
    if (pore_of_[i] >= 0) {
      const double phi = 1.0 - f[i];
      ratio[i] = ice_ratio_ * phi;
      eigen[i] = free_strain(phi, pores_[pore_of_[i]].saturation);
    }
  solid.set_stiffness_ratio(ratio);
  solid.set_eigenstrain(eigen);
}

}  // namespace frostwall::pd
