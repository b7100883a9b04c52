// The brine film's heat transfer coefficient in a freeze pipe:
// brine goes down the supply pipe and returns up the annulus between it and
// the freeze pipe, taking heat from the freeze pipe's wall. Fully developed
// flow, hydraulic diameter D_h = d_o - d_i, Re = rho v D_h / mu, Pr = mu c_p / k:
//  - laminar, Re <= 2300: Nu = 4.9 (annulus, heat through the outer wall,
//    the inner one insulated; a fixed design value, whatever the radius ratio);
//  - turbulent, Re >= 1e4: Gnielinski, Nu = (f/8)(Re - 1000) Pr /
//    (1 + 12.7 sqrt(f/8)(Pr^(2/3) - 1)), f = (0.79 ln Re - 1.64)^-2;
//  - between: transitional, linear in Re between the two ends (Gnielinski's
//    own recommendation, VDI Heat Atlas G1 / Int. J. Heat Mass Transfer 2013),
//    flagged: the film there is uncertain.
// h = Nu k / D_h on the freeze pipe's inner wall; referred to its outer wall
// (the ground's side, where the Robin condition sits) by d_o / d so that the
// heat per metre is the same. The steel wall's own resistance is left out
// (about 1e-4 m2 K / W for 5 mm of steel: under 5 % of a 400 W/(m2 K) film).
#pragma once

#include <string_view>

#include "project/design.hpp"

namespace frostwall::design {

using project::Annulus;
using project::BrineProperties;

enum class FlowRegime { laminar, transitional, turbulent };
std::string_view name(FlowRegime r);

struct FilmCoefficient {
  double reynolds = 0.0, prandtl = 0.0, nusselt = 0.0;
  FlowRegime regime = FlowRegime::laminar;
  double h_inner = 0.0;  // W/(m2 K) on the freeze pipe's inner wall
  double h = 0.0;        // referred to its outer wall of diameter pipe_diameter
};

// Gnielinski's turbulent Nusselt number (Re >= 1e4 in use; the formula
// itself holds from about 2300).
double gnielinski_nusselt(double reynolds, double prandtl);

FilmCoefficient annulus_film(const Annulus& a, double pipe_diameter);

}  // namespace frostwall::design
