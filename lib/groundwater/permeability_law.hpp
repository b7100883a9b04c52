// How ice in the pores cuts the soil's permeability: k = k_sat k_r(S_ice),
// with S_ice = 1 - f the ice's share of the pore water (f the liquid
// fraction of the phase-change law). One small law per choice, named in the
// project file and recorded in summary.json:
//  - impedance: k_r = 10^(-Omega S_ice) (Hansson et al. 2004: Omega = 7;
//    the InterFrost benchmarks: Omega = 50);
//  - kozeny_carman: Kozeny-Carman on the liquid porosity n_l = n f,
//    k_r = [n_l^3 / (1 - n_l)^2] / [n^3 / (1 - n)^2];
//  - threshold: k_r = 1 while f >= f_c, impermeable below;
//  - constant: k_r = 1, ice or not (water at a fixed velocity, as in the
//    benchmarks with advection through frozen ground).
// Every law is held at or above `floor` (relative), so the flow problem
// stays solvable where the ground is frozen solid.
#pragma once

#include <string>

#include "project/groundwater.hpp"

namespace frostwall::groundwater {

using project::PermeabilityModel;

// The settings as the project file gives them (model, impedance, porosity,
// threshold liquid fraction, floor), evaluated.
struct PermeabilityLaw : project::PermeabilitySettings {
  // k / k_sat at liquid fraction f in [0, 1] (clamped): 1 at f = 1, never
  // rising as ice forms (f falls), never below `floor`.
  double relative(double liquid_fraction) const;
  std::string name() const;
};

// The law as the project file gives it.
PermeabilityLaw permeability_law(const project::PermeabilitySettings& s);

// "impedance", "kozeny_carman", "threshold", "constant"; false if unknown.
bool permeability_model_from_name(const std::string& name, PermeabilityModel& model);

}  // namespace frostwall::groundwater
