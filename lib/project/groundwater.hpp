// The "groundwater" block of a shaft project: water flowing through the
// freezing ground (issue 17). The soil's permeability (m^2, or hydraulic
// conductivity in m/s), its porosity, how ice cuts the permeability
// (lib/porous_flow/permeability_law.hpp) and the regional flow far from
// the shaft. Absent: still water, and the thermal run is unchanged.
#pragma once

#include <array>
#include <optional>

#include "porous_flow/permeability_law.hpp"

namespace frostwall::project {

struct Groundwater {
  // One of the two, as given; the other follows from the water below
  // (K = k rho_w g / mu_w).
  std::optional<double> permeability;            // m^2
  std::optional<double> hydraulic_conductivity;  // m/s
  porous_flow::PermeabilityLaw law;              // its porosity is the soil's
  // The regional Darcy flux far from the shaft, m/s (given in m/d or m/s).
  std::array<double, 2> darcy_flux{0.0, 0.0};
  // Pore water (defaults near 5 degC): J/(m3 K) heat capacity per volume, Pa s.
  double water_density = 1000.0;
  double water_heat_capacity = 4200.0;  // J/(kg K)
  double water_viscosity = 1.5e-3;
  // The flow is solved again when some particle's relative permeability has
  // changed by this factor since the last solve (0.1: 10 %).
  double resolve_tolerance = 0.1;

  double speed() const;            // |q|, m/s
  double permeability_m2() const;  // k, m^2 (from K when K was given)
};

}  // namespace frostwall::project
