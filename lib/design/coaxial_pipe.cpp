#include "design/coaxial_pipe.hpp"

#include <cmath>

namespace frostwall::design {

namespace {

constexpr double laminar_below = 2300.0, turbulent_from = 1e4;

// Gnielinski with Konakov's friction factor and the entrance term.
double turbulent(double reynolds, double prandtl, double xi, double diameter_over_length) {
  return xi / 8.0 * reynolds * prandtl / (1.0 + 12.7 * std::sqrt(xi / 8.0) * (std::pow(prandtl, 2.0 / 3.0) - 1.0)) *
         (1.0 + std::pow(diameter_over_length, 2.0 / 3.0));
}

double konakov(double reynolds) { return std::pow(1.8 * std::log10(reynolds) - 1.5, -2.0); }

// Laminar below 2300, turbulent from 1e4 (factor times the pipe's value),
// linear in Re between the laminar value and the turbulent one at 1e4.
double blended(double laminar, double factor, double reynolds, double prandtl, double diameter_over_length) {
  if (reynolds < laminar_below) return laminar;
  if (reynolds >= turbulent_from) return factor * turbulent(reynolds, prandtl, konakov(reynolds), diameter_over_length);
  const double g = (reynolds - laminar_below) / (turbulent_from - laminar_below);
  return (1.0 - g) * laminar + g * factor * turbulent(turbulent_from, prandtl, 0.0308, diameter_over_length);
}

}  // namespace

double pipe_nusselt(double reynolds, double prandtl, double diameter_over_length) {
  return blended(4.364, 1.0, reynolds, prandtl, diameter_over_length);
}

double annulus_nusselt(double reynolds, double prandtl, double a, double diameter_over_length) {
  const double laminar = 3.66 + (4.0 - 0.102 / (a + 0.02)) * std::pow(a, 0.04);
  const double factor = (0.86 * std::pow(a, 0.84) + 1.0 - 0.14 * std::pow(a, 0.6)) / (1.0 + a);
  return blended(laminar, factor, reynolds, prandtl, diameter_over_length);
}

CoaxialResistances coaxial_resistances(const CoaxialPipe& p, const Brine& b, double flow) {
  const double d_ii = p.inner_diameter - 2.0 * p.inner_wall, d_io = p.inner_diameter;
  const double d_oi = p.outer_diameter - 2.0 * p.outer_wall, d_oo = p.outer_diameter;
  const double prandtl = b.viscosity * b.heat_capacity / b.conductivity;
  CoaxialResistances r;

  const double v_inner = flow / (M_PI / 4.0 * d_ii * d_ii);
  r.inner.reynolds = b.density * v_inner * d_ii / b.viscosity;
  r.inner.prandtl = prandtl;
  r.inner.nusselt = pipe_nusselt(r.inner.reynolds, prandtl, d_ii / p.length);
  r.inner.h = r.inner.nusselt * b.conductivity / d_ii;

  const double D_h = d_oi - d_io;
  const double v_annulus = flow / (M_PI / 4.0 * (d_oi * d_oi - d_io * d_io));
  r.annulus.reynolds = b.density * v_annulus * D_h / b.viscosity;
  r.annulus.prandtl = prandtl;
  r.annulus.nusselt = annulus_nusselt(r.annulus.reynolds, prandtl, d_io / d_oi, D_h / p.length);
  r.annulus.h = r.annulus.nusselt * b.conductivity / D_h;

  r.channels = 1.0 / (M_PI * d_ii * r.inner.h) + std::log(d_io / d_ii) / (2.0 * M_PI * p.inner_conductivity) +
               1.0 / (M_PI * d_io * r.annulus.h);
  r.ground = 1.0 / (M_PI * d_oi * r.annulus.h) + std::log(d_oo / d_oi) / (2.0 * M_PI * p.outer_conductivity);
  return r;
}

}  // namespace frostwall::design
