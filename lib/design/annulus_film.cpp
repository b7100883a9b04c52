#include "design/annulus_film.hpp"

#include <cmath>

namespace frostwall::design {

namespace {
constexpr double laminar_end = 2300.0, turbulent_start = 1e4, laminar_nusselt = 4.9;
}

std::string_view name(FlowRegime r) {
  switch (r) {
    case FlowRegime::laminar: return "laminar";
    case FlowRegime::transitional: return "transitional";
    case FlowRegime::turbulent: return "turbulent";
  }
  return "?";
}

double gnielinski_nusselt(double Re, double Pr) {
  const double f = std::pow(0.79 * std::log(Re) - 1.64, -2.0);
  return f / 8.0 * (Re - 1000.0) * Pr / (1.0 + 12.7 * std::sqrt(f / 8.0) * (std::pow(Pr, 2.0 / 3.0) - 1.0));
}

FilmCoefficient annulus_film(const Annulus& a, double pipe_diameter) {
  FilmCoefficient film;
  const double Dh = a.outer_diameter - a.inner_diameter;
  const double area = M_PI / 4.0 * (a.outer_diameter * a.outer_diameter - a.inner_diameter * a.inner_diameter);
  const auto& b = a.brine;
  film.reynolds = b.density * (a.flow / area) * Dh / b.viscosity;
  film.prandtl = b.viscosity * b.heat_capacity / b.conductivity;
  if (film.reynolds <= laminar_end) {
    film.nusselt = laminar_nusselt;
  } else if (film.reynolds >= turbulent_start) {
    film.regime = FlowRegime::turbulent;
    film.nusselt = gnielinski_nusselt(film.reynolds, film.prandtl);
  } else {
    film.regime = FlowRegime::transitional;
    const double g = (film.reynolds - laminar_end) / (turbulent_start - laminar_end);
    film.nusselt = (1.0 - g) * laminar_nusselt + g * gnielinski_nusselt(turbulent_start, film.prandtl);
  }
  film.h_inner = film.nusselt * b.conductivity / Dh;
  film.h = film.h_inner * a.outer_diameter / pipe_diameter;
  return film;
}

}  // namespace frostwall::design
