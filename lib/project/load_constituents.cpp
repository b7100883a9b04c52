#include "project/load_constituents.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

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

// Saturated ground: unfrozen, the pores hold water; frozen, ice (between
// them, soil.freezing_curve). Per unit volume:
//   rho C = (1 - n) rho_s c_s + n rho_f c_f          (f the pore fluid)
//   k     = (1 - n) k_s + n k_f   (arithmetic)  or  k_s^(1-n) k_f^n   (geometric)
//   latent heat = n rho_i L (the mass of the ice the pores hold).
// The soil's density is the unfrozen bulk density; heat capacity and latent
// heat are per kg of it, so that density x each is the volumetric value.
Soil soil_from_constituents(const Node& n) {
  Soil soil;
  // (The other soil's fields are refused by the caller, one line each.)
  n.object({"name", "porosity", "solid", "water", "ice", "conductivity_mixing", "freezing_point", "freezing_curve",
            "density", "unfrozen", "frozen", "latent_heat", "freezing_range"});
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
  soil.latent_heat = porosity * ice.density * latent / soil.density;
  soil.freezing_point = n["freezing_point"].number().value_or(0.0);
  soil.geometric_conductivity = geometric;
  soil.porosity = porosity;
  read_freezing_curve(n, soil, porosity * water.density / ((1.0 - porosity) * solid.density));
  return soil;
}

void read_freezing_curve(const Node& soil_node, Soil& soil, double water_content) {
  const Node n = soil_node["freezing_curve"];
  if (soil_node["freezing_range"].present()) {
    if (n.present())
      soil_node["freezing_range"].problem(R"(give the range as freezing_curve {"model": "linear", "range": ...})");
    soil.freezing_range = soil_node["freezing_range"].non_negative().value_or(0.0);
    if (soil.freezing_range > 0.0) soil.freezing_curve.model = CurveModel::linear;
  }
  if (!n.present() || !n.object({"model", "range", "width", "residual_saturation", "alpha", "beta", "water_content"}))
    return;
  auto& c = soil.freezing_curve;
  c.model = n["model"]
                .required()
                .choice<CurveModel>("freezing curve", {{"step", CurveModel::step},
                                                       {"linear", CurveModel::linear},
                                                       {"exponential", CurveModel::exponential},
                                                       {"power", CurveModel::power}})
                .value_or(CurveModel::step);
  auto refuse_others = [&](std::initializer_list<const char*> own) {
    for (const char* key : {"range", "width", "residual_saturation", "alpha", "beta", "water_content"})
      if (n[key].present() &&
          std::find_if(own.begin(), own.end(), [&](const char* o) { return std::string_view(o) == key; }) == own.end())
        n[key].problem("not a field of the " + n["model"].json().get<std::string>() + " curve");
  };
  switch (c.model) {
    case CurveModel::step: refuse_others({}); break;
    case CurveModel::linear:
      refuse_others({"range"});
      soil.freezing_range = n["range"].required().positive().value_or(0.0);
      break;
    case CurveModel::exponential:
      refuse_others({"width", "residual_saturation"});
      c.width = n["width"].required().positive().value_or(1.0);
      c.residual_saturation = n["residual_saturation"].non_negative().value_or(0.0);
      if (c.residual_saturation >= 0.5)
        n["residual_saturation"].problem(
            "must be below 0.5 (ground counts as frozen once half its water is ice), got " +
            n["residual_saturation"].shown());
      break;
    case CurveModel::power: {
      refuse_others({"alpha", "beta", "water_content"});
      c.alpha = n["alpha"].required().positive().value_or(1.0);
      c.beta = n["beta"].required().number().value_or(-1.0);
      if (!(c.beta < 0.0))
        n["beta"].problem("must be negative (less water stays liquid the colder), got " + n["beta"].shown());
      const Node w = water_content > 0.0 ? n["water_content"] : n["water_content"].required();
      c.water_content = w.positive().value_or(water_content > 0.0 ? water_content : 1.0);
      // The share still liquid at the phase law table's end.
      const double Tf = soil.freezing_point;
      if (c.beta < 0.0 && c.liquid_fraction(c.bottom(Tf), Tf) >= 0.5)
        n.problem("keeps half its water liquid 60 K below its onset: it never counts as frozen");
      break;
    }
  }
}

}  // namespace frostwall::project::detail
