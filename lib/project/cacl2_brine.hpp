// Calcium chloride brine (CaCl2 in water), the usual brine of ground
// freezing plants: its properties against temperature and concentration
// from Melinder's fit (Properties of Secondary Working Fluids for Indirect
// Systems, IIF-IIR 2010), as CoolProp stores it (incompressible fluid
// "MCA"): f(x, t) = sum c_ij (x - xm)^i (t - tm)^j, x in mass %, t in degC,
// xm = 18.7414, tm = 7.5257, i <= 5, j <= 3, i + j <= 5. Valid from the
// solution's freezing point to +40 C, for mass fractions up to 0.30;
// viscosity is the least certain (VDI's Heat Atlas gives 27 % more at -30 C
// and 29.9 %; density, heat capacity and conductivity agree within 0.5 %).
#pragma once

#include "project/design.hpp"

namespace frostwall::project {

// The brine at mass fraction x (0..0.30) and temperature T (degC).
BrineProperties cacl2_brine(double mass_fraction, double T);
// Where the solution begins to freeze, degC (ice first below the eutectic
// concentration, about 0.30).
double cacl2_freezing_point(double mass_fraction);

}  // namespace frostwall::project
