// Reads the "groundwater" block (project/groundwater.hpp).
#include <cmath>

#include "project/load_groundwater.hpp"
#include "project/units.hpp"

namespace frostwall::project {

double Groundwater::speed() const { return std::hypot(darcy_flux[0], darcy_flux[1]); }

bool Groundwater::flows_coupled() const { return advection == Advection::coupled && flows(); }

double Groundwater::permeability_m2() const {
  if (permeability) return *permeability;
  return hydraulic_conductivity.value_or(0.0) * water_viscosity / (water_density * 9.81);
}

double Groundwater::conductivity_m_per_s() const {
  if (hydraulic_conductivity) return *hydraulic_conductivity;
  return permeability.value_or(0.0) * water_density * 9.81 / water_viscosity;
}

namespace detail {

Groundwater read_groundwater(const Node& n, bool plain) {
  Groundwater g;
  n.object({"permeability", "hydraulic_conductivity", "porosity", "permeability_law", "darcy_flux",
            "hydraulic_gradient", "unit", "water", "resolve_tolerance", "advection"});
  g.permeability = n["permeability"].positive();
  g.hydraulic_conductivity = n["hydraulic_conductivity"].positive();
  if (n["permeability"].present() == n["hydraulic_conductivity"].present())
    n["permeability"].problem(R"(give either "permeability" (m^2) or "hydraulic_conductivity" (m/s))");
  if (const auto porosity = n["porosity"].required().positive()) {
    if (*porosity >= 1.0) n["porosity"].problem(fmt::format("must be below 1, got {}", *porosity));
    g.law.porosity = *porosity;
  }
  if (const Node law = n["permeability_law"]; law.object({"model", "impedance", "liquid_fraction", "floor"})) {
    if (const auto m = law["model"].required().choice<PermeabilityModel>(
            "permeability law", {{"impedance", PermeabilityModel::impedance},
                                 {"kozeny_carman", PermeabilityModel::kozeny_carman},
                                 {"threshold", PermeabilityModel::threshold},
                                 {"constant", PermeabilityModel::constant}}))
      g.law.model = *m;
    if (const auto omega = law["impedance"].positive()) g.law.impedance = *omega;
    if (law["impedance"].present() && g.law.model != PermeabilityModel::impedance)
      law["impedance"].problem(R"(only used with "model": "impedance")");
    if (const auto f = law["liquid_fraction"].positive()) {
      if (*f >= 1.0) law["liquid_fraction"].problem(fmt::format("must be below 1, got {}", *f));
      g.law.threshold_liquid_fraction = *f;
    }
    if (law["liquid_fraction"].present() && g.law.model != PermeabilityModel::threshold)
      law["liquid_fraction"].problem(R"(only used with "model": "threshold")");
    if (const auto floor = law["floor"].positive()) {
      if (*floor >= 1.0) law["floor"].problem(fmt::format("must be below 1, got {}", *floor));
      g.law.floor = *floor;
    }
  }
  double per_second = 1.0 / seconds_per_day;
  if (const auto unit = n["unit"].choice<double>("unit", {{"m/d", 1.0 / seconds_per_day}, {"m/s", 1.0}}))
    per_second = *unit;
  if (plain) {
    for (const char* key : {"darcy_flux", "hydraulic_gradient"})
      if (n[key].present()) n[key].problem("a rectangle's flow follows the heads of its faces");
  } else if (n["darcy_flux"].present() == n["hydraulic_gradient"].present())
    n["darcy_flux"].problem(
        R"(give either "darcy_flux" (the regional flux) or "hydraulic_gradient" (the head's fall per metre))");
  if (const Node i = n["hydraulic_gradient"]; i.present()) {
    if (i.array() != std::size_t{2}) i.problem(fmt::format("must be [i_x, i_y], got {}", i.shown()));
    else {
      g.hydraulic_gradient.emplace();
      for (std::size_t d = 0; d < 2; ++d)
        if (const auto v = i[d].number()) (*g.hydraulic_gradient)[d] = *v;
    }
    if (n["unit"].present()) n["unit"].problem(R"(only used with "darcy_flux" (a gradient has no unit))");
  }
  if (const Node q = n["darcy_flux"]; q.present()) {
    if (q.array() != std::size_t{2}) q.problem(fmt::format("must be [q_x, q_y], got {}", q.shown()));
    else
      for (std::size_t d = 0; d < 2; ++d)
        if (const auto v = q[d].number()) g.darcy_flux[d] = *v * per_second;
  }
  if (const Node w = n["water"]; w.object({"density", "heat_capacity", "viscosity"})) {
    g.water_density = w["density"].positive().value_or(g.water_density);
    g.water_heat_capacity = w["heat_capacity"].positive().value_or(g.water_heat_capacity);
    g.water_viscosity = w["viscosity"].positive().value_or(g.water_viscosity);
  }
  // Darcy's law far from the shaft: q = K i, with the water given above.
  if (g.hydraulic_gradient)
    for (std::size_t d = 0; d < 2; ++d) g.darcy_flux[d] = g.conductivity_m_per_s() * (*g.hydraulic_gradient)[d];
  if (const auto tol = n["resolve_tolerance"].positive()) g.resolve_tolerance = *tol;
  if (const auto a = n["advection"].choice<Advection>("advection scheme", {{"coupled", Advection::coupled},
                                                                           {"implicit", Advection::implicit},
                                                                           {"limited", Advection::limited},
                                                                           {"upwind", Advection::upwind}}))
    g.advection = *a;
  return g;
}

}  // namespace detail
}  // namespace frostwall::project
