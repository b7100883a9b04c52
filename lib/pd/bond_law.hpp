// The bond law of bond-based peridynamics in 2-D (physics.md section 5):
// pair force density f = c (s - s_T) mu e per unit volume squared, s the
// bond stretch, s_T the bond's thermal stretch, mu 0 once broken, e the
// deformed bond direction. The micromodulus c matches the continuum's
// elastic energy (uniform stretch s: W = pi c s^2 delta^3 / 6 per unit
// volume, t = 1):
//     plane strain c = 48 E / (5 pi delta^3)   (nu fixed at 1/4)
//     plane stress c =  9 E / (pi delta^3)     (nu fixed at 1/3)
// Critical stretch from the fracture energy G0 (the work to break every
// bond across a unit crack): plane strain sqrt(5 pi G0 / (12 E delta)),
// plane stress sqrt(4 pi G0 / (9 E delta)).
// Thermal stretch: a free in-plane expansion. In plane stress it is
// alpha dT; in plane strain the body cannot expand out of plane, and the
// in-plane strain of free expansion is (1 + nu) alpha dT: that is what a
// bond takes, so a uniformly heated free body stays stress-free with the
// exact plane-strain displacement.
#pragma once

#include <cmath>
#include <limits>
#include <numbers>

#include "project/mechanics.hpp"

namespace frostwall::pd {

struct BondLaw {
  double micromodulus = 0.0;  // c, N/m^6 per metre of depth
  double critical_stretch = std::numeric_limits<double>::infinity();
  double thermal_stretch_per_K = 0.0;  // s_T = this x (bond's mean temperature change)
  double horizon = 0.0;

  // The continuum's elastic energy density under a uniaxial strain eps
  // along one axis, as the bonds would store it: pi c eps^2 delta^3 / 16.
  double uniaxial_energy(double eps) const {
    return std::numbers::pi * micromodulus * eps * eps * std::pow(horizon, 3) / 16.0;
  }
};

inline BondLaw make_bond_law(const project::Mechanics& m, double horizon) {
  const double E = m.material.elastic_modulus, d3 = std::pow(horizon, 3), pi = std::numbers::pi;
  BondLaw law;
  law.horizon = horizon;
  const bool strain = m.plane == project::Plane::strain;
  law.micromodulus = strain ? 48.0 * E / (5.0 * pi * d3) : 9.0 * E / (pi * d3);
  if (m.material.fracture_energy) {
    const double G0 = *m.material.fracture_energy;
    law.critical_stretch = strain ? std::sqrt(5.0 * pi * G0 / (12.0 * E * horizon))
                                  : std::sqrt(4.0 * pi * G0 / (9.0 * E * horizon));
  }
  law.thermal_stretch_per_K = (strain ? 1.0 + m.material.poisson_ratio : 1.0) * m.material.thermal_expansion;
  return law;
}

}  // namespace frostwall::pd
