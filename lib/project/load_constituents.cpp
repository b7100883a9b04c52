#include "project/load_constituents.hpp"

#include <cmath>

namespace frostwall::project::detail {

namespace {

struct Constituent {
  double density = 0.0, heat_capacity = 0.0, conductivity = 0.0;
};

Constituent read_constituent(const Node& n, bool with_latent_heat) {
  Constituent c;
  if (with_latent_heat ? !n.object({"density", "heat_capacity", "conductivity", "latent_heat"})
                       : !n.object({"density", "heat_capacity", "conductivity"}))
    return c;
  c.density = n["density"].required().positive().value_or(0.0);
  c.heat_capacity = n["heat_capacity"].required().positive().value_or(0.0);
  c.conductivity = n["conductivity"].required().positive().value_or(0.0);
  return c;
}

}  // namespace

// Saturated ground, the step freezing curve: unfrozen, the pores hold water;
// frozen, ice. Per unit volume:
//   rho C = (1 - n) rho_s c_s + n rho_f c_f          (f the pore fluid)
//   k     = (1 - n) k_s + n k_f   (arithmetic)  or  k_s^(1-n) k_f^n   (geometric)
//   latent heat = n rho_w L.
// The soil's density is the unfrozen bulk density; heat capacity and latent
// heat are per kg of it, so that density x each is the volumetric value.
Soil soil_from_constituents(const Node& n) {
  Soil soil;
  // (The other soil's fields are refused by the caller, one line each.)
  n.object({"name", "porosity", "solid", "water", "ice", "conductivity_mixing", "freezing_point", "density", "unfrozen",
            "frozen", "latent_heat", "freezing_range"});
  soil.name = n["name"].string().value_or("soil from its constituents");
  const double porosity = n["porosity"].required().positive().value_or(0.0);
  if (porosity >= 1.0) n["porosity"].problem("must be below 1, got " + n["porosity"].shown());
  const Constituent solid = read_constituent(n["solid"].required(), false);
  const Constituent water = read_constituent(n["water"].required(), true);
  const Constituent ice = read_constituent(n["ice"].required(), false);
  const double latent = n["water"]["latent_heat"].required().positive().value_or(0.0);
  const bool geometric = n["conductivity_mixing"]
                             .choice<bool>("conductivity mixing", {{"arithmetic", false}, {"geometric", true}})
                             .value_or(false);
  auto mix = [&](double fluid) {
    return geometric ? std::pow(solid.conductivity, 1.0 - porosity) * std::pow(fluid, porosity)
                     : (1.0 - porosity) * solid.conductivity + porosity * fluid;
  };
  soil.density = (1.0 - porosity) * solid.density + porosity * water.density;
  if (!(soil.density > 0.0)) return soil;
  const double solid_heat = (1.0 - porosity) * solid.density * solid.heat_capacity;
  soil.unfrozen.heat_capacity = (solid_heat + porosity * water.density * water.heat_capacity) / soil.density;
  soil.frozen.heat_capacity = (solid_heat + porosity * ice.density * ice.heat_capacity) / soil.density;
  soil.unfrozen.conductivity = {mix(water.conductivity), mix(water.conductivity)};
  soil.frozen.conductivity = {mix(ice.conductivity), mix(ice.conductivity)};
  soil.latent_heat = porosity * water.density * latent / soil.density;
  soil.freezing_point = n["freezing_point"].number().value_or(0.0);
  return soil;
}

}  // namespace frostwall::project::detail
