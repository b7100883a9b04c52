// Fluid drag on one grain: one small type per law (CFDEMcoupling's
// subModels style; the project will choose one by name). Velocities are explicit about their
// kind: `slip` is the interstitial slip u_f - u_p (the fluid's velocity in
// the pores minus the grain's); the superficial (Darcy) slip is
// porosity x slip. The Reynolds number is the grain's on the superficial
// slip, Re = rho_f eps |u_f - u_p| d / mu (Di Felice 1994).
#pragma once

#include "particles/vec.hpp"

namespace frostwall::pore_water {

using Vec3 = particles::Vec<3>;

struct Fluid {
  double density = 1000.0;  // kg/m3
  double viscosity = 1e-3;  // dynamic, Pa s
};

// Schiller & Naumann's drag coefficient of a sphere: 24 / Re (1 + 0.15
// Re^0.687) below Re 1000, 0.44 above.
double schiller_naumann_cd(double reynolds);

class DragLaw {
 public:
  virtual ~DragLaw() = default;
  // The drag force (N) on a grain of diameter d at the given porosity
  // round it and interstitial slip velocity.
  virtual Vec3 force(const Fluid& fluid, double diameter, double porosity, const Vec3& slip) const = 0;
};

// Di Felice (1994): F = 1/2 Cd rho_f (pi d^2 / 4) eps^2 |v| v eps^(-chi),
// Cd = (0.63 + 4.8 / sqrt(Re))^2 (Dallavalle), chi = 3.7 - 0.65
// exp(-(1.5 - log10 Re)^2 / 2). At porosity 1: Dallavalle's single sphere.
class DiFeliceDrag final : public DragLaw {
 public:
  Vec3 force(const Fluid& fluid, double diameter, double porosity, const Vec3& slip) const override;
};

// Schiller & Naumann (1933), a single sphere; no voidage function.
class SchillerNaumannDrag final : public DragLaw {
 public:
  Vec3 force(const Fluid& fluid, double diameter, double porosity, const Vec3& slip) const override;
};

}  // namespace frostwall::pore_water
