// The "groundwater" block of a shaft project: water flowing through the
// freezing ground. The soil's permeability (m^2, or hydraulic
// conductivity in m/s), its porosity, how ice cuts the permeability
// (lib/groundwater/permeability_law.hpp) and the regional flow far from
// the shaft. Absent: still water, and the thermal run is unchanged.
#pragma once

#include <array>
#include <optional>

namespace frostwall::project {

// How ice cuts the permeability, as given (groundwater/permeability_law.hpp
// evaluates it): k_r = 10^(-impedance S_ice), Kozeny-Carman on the liquid
// porosity, a threshold liquid fraction, or unchanged by ice (constant: the
// fixed-velocity benchmarks); never below `floor`.
enum class PermeabilityModel { impedance, kozeny_carman, threshold, constant };
struct PermeabilitySettings {
  PermeabilityModel model = PermeabilityModel::impedance;
  double impedance = 7.0;                  // Omega
  double porosity = 0.35;                  // n, for kozeny_carman
  double threshold_liquid_fraction = 0.1;  // f_c, for threshold
  double floor = 1e-6;                     // smallest k_r
};

// How the heat the water carries is stepped (thermal/heat_advection.hpp):
// coupled (the default): limited faces inside the conduction's backward-
// Euler step, one system for both at any step; explicit limited or upwind,
// held to the advective Courant limit (the reference; with an explicit
// integrator); or implicit upwind split from the conduction (screening).
enum class Advection { limited, upwind, implicit, coupled };

struct Groundwater {
  // One of the two, as given; the other follows from the water below
  // (K = k rho_w g / mu_w).
  std::optional<double> permeability;            // m^2
  std::optional<double> hydraulic_conductivity;  // m/s
  PermeabilitySettings law;                      // its porosity is the soil's
  // The regional Darcy flux far from the shaft, m/s (given in m/d or m/s,
  // or from the hydraulic gradient: q = K i).
  std::array<double, 2> darcy_flux{0.0, 0.0};
  // The head's fall per metre along x and y far from the shaft (from
  // piezometers), when given instead of the flux.
  std::optional<std::array<double, 2>> hydraulic_gradient;
  // Pore water (defaults near 5 degC): J/(m3 K) heat capacity per volume, Pa s.
  double water_density = 1000.0;
  double water_heat_capacity = 4200.0;  // J/(kg K)
  double water_viscosity = 1.5e-3;
  // The flow is solved again when the share of the water whose path ice
  // has changed since the last solve exceeds this: each particle's
  // throughflow weighted by its permeability's relative change (at most 1).
  double resolve_tolerance = 3e-4;
  Advection advection = Advection::coupled;

  // Plain geometries: the largest difference between two faces' heads, m
  // (the flow follows the faces' heads; darcy_flux stays 0).
  double head_difference = 0.0;

  double speed() const;  // |q|, m/s
  // Water moves: a regional flux, or faces at different heads.
  bool flows() const { return speed() > 0.0 || head_difference > 0.0; }
  double permeability_m2() const;       // k, m^2 (from K when K was given)
  double conductivity_m_per_s() const;  // K, m/s (from k when k was given)
  // Water flows (|q| > 0) and its heat is stepped by the coupled scheme,
  // inside the conduction's backward-Euler step.
  bool flows_coupled() const;
};

}  // namespace frostwall::project
