// The pressure gradient a bed of grains opposes to a flow through it:
// what the coarse fluid grid's momentum equation needs, cell by cell, and
// what the grains feel back. U is the superficial (Darcy) velocity, the
// flow rate per unit of total area; the interstitial velocity in the
// pores is U / porosity (a mix-up costs a factor of the porosity).
//  - Ergun (1952): -dp/dx = 150 mu (1 - e)^2 U / (e^3 d^2)
//                          + 1.75 rho (1 - e) U^2 / (e^3 d), dense beds;
//  - Wen & Yu (1966): -dp/dx = 3/4 Cd rho (1 - e) U^2 e^-2.65 / (e^2 d),
//    Cd Schiller-Naumann's on Re = rho U d / mu,
//    dilute beds: at porosity 1 the grains' Schiller-Naumann drag;
//  - blended (Huilin & Gidaspow 2003): phi Ergun + (1 - phi) Wen-Yu with
//    phi = 1/2 + arctan(262.5 ((1 - e) - 0.2)) / pi, so the switch at
//    porosity 0.8 is smooth.
#pragma once

#include "pore_water/drag_law.hpp"

namespace frostwall::pore_water {

double ergun_gradient(const Fluid& fluid, double porosity, double diameter, double superficial_velocity);
double wen_yu_gradient(const Fluid& fluid, double porosity, double diameter, double superficial_velocity);
double bed_gradient(const Fluid& fluid, double porosity, double diameter, double superficial_velocity);
// The superficial velocity at which Ergun's gradient reaches `gradient`
// (Pa/m; by bisection, it rises monotonically): a bed's minimum
// fluidisation velocity when that is its buoyant weight per volume.
double ergun_velocity(const Fluid& fluid, double porosity, double diameter, double gradient);
// bed_gradient / (1 - porosity), written out so that it stays finite as
// the porosity reaches 1: the gradient per unit of solid fraction.
double bed_gradient_per_solid(const Fluid& fluid, double porosity, double diameter, double superficial_velocity);

}  // namespace frostwall::pore_water
