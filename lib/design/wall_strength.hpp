// The thickness a frozen shaft wall needs to carry the lateral ground
// pressure, from the classical thick-cylinder formulas, with a
// the excavation radius, P the lateral pressure at the layer's depth and s
// the allowable strength of the frozen soil at the wall's mean temperature
// (allowable factor times the uniaxial compressive strength):
//  - Lame, elastic, Tresca:     E = a (sqrt(s / (s - 2 P)) - 1),        s > 2 P
//  - Lame, elastic, von Mises:  E = a (sqrt(s / (s - sqrt(3) P)) - 1),  s > sqrt(3) P
//    (the inner face of an elastic thick cylinder under outer pressure
//    reaches the criterion: sigma_theta(a) = 2 P b^2 / (b^2 - a^2), sigma_r
//    = 0; von Mises in plane strain with sigma_z the mean of the two, so
//    sqrt(3)/2 sigma_theta = s);
//  - Domke:                     E = a (0.29 (P / s) + 2.3 (P / s)^2)
//    (an empirical fit of elasto-plastic wall design, Domke 1915, as used in
//    German shaft-sinking practice);
//  - plastic limit, Tresca:     E = a (exp(P / s) - 1)
//    (the whole wall yielding: d sigma_r / dr = s / r, sigma_r(a) = 0);
//  - plastic limit, Mohr-Coulomb, with cohesion c and friction angle phi:
//    sigma_theta = sigma_c + N sigma_r, N = (1 + sin phi) / (1 - sin phi),
//    sigma_c = 2 c cos phi / (1 - sin phi) (the allowable factor on c), so
//    E = a ((1 + (N - 1) P / sigma_c)^(1 / (N - 1)) - 1); it tends to the
//    Tresca limit with s = 2 c as phi -> 0.
// An invalid formula (the Lame forms past their limit: the elastic wall
// cannot carry P at any thickness) gives nullopt.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

#include "project/design.hpp"

namespace frostwall::design {

using Formula = project::WallFormula;
inline constexpr std::array<Formula, 5> all_formulas = {Formula::lame_tresca, Formula::lame_mises, Formula::domke,
                                                        Formula::plastic_tresca, Formula::plastic_mohr_coulomb};
using project::name;  // the formula's name in the project file
using project::StrengthLaw;
using project::table_problem;

// Mohr-Coulomb parameters of the frozen soil (the cohesion at the wall's
// mean temperature, MPa, already times the allowable factor).
struct MohrCoulomb {
  double cohesion = 0.0;        // MPa
  double friction_angle = 0.0;  // degrees
};

// m; a in m, P and s in MPa. plastic_mohr_coulomb needs `mc` (nullopt without).
std::optional<double> required_thickness(Formula f, double a, double P, double s, const MohrCoulomb* mc = nullptr);

}  // namespace frostwall::design
