#include "calibrate/parameters.hpp"

#include <cmath>

#include "project/units.hpp"

namespace frostwall::calibrate {

const char* parameter_unit(CalibratedParameter p) {
  switch (p) {
    case CalibratedParameter::initial_temperature: return "degC";
    case CalibratedParameter::darcy_flux: return "m/d";
    default: return "factor";
  }
}

project::Project with_values(const project::Project& base, const std::vector<FittedParameter>& parameters,
                             const std::vector<double>& values) {
  project::Project p = base;
  for (std::size_t k = 0; k < parameters.size(); ++k) {
    const double v = values.at(k);
    switch (parameters[k].which) {
      case CalibratedParameter::conductivity_frozen:
        for (auto& c : p.soil.frozen.conductivity) c *= v;
        break;
      case CalibratedParameter::conductivity_unfrozen:
        for (auto& c : p.soil.unfrozen.conductivity) c *= v;
        break;
      case CalibratedParameter::latent_heat: p.soil.latent_heat *= v; break;
      case CalibratedParameter::initial_temperature:
        // Ground at one temperature to the far field stays so.
        if (p.domain.far_field_temperature == p.domain.initial_temperature) p.domain.far_field_temperature = v;
        p.domain.initial_temperature = v;
        break;
      case CalibratedParameter::darcy_flux: {
        auto& q = p.groundwater->darcy_flux;
        const double speed = std::hypot(q[0], q[1]);
        for (auto& c : q) c *= v / project::seconds_per_day / speed;
        p.groundwater->hydraulic_gradient.reset();
        break;
      }
    }
  }
  return p;
}

project::Project fit_project(const project::Project& base, const std::vector<double>& values) {
  project::Project p = with_values(base, base.calibration->parameters, values);
  p.numerics.step_change = base.calibration->step_change;
  return p;
}

namespace {

nlohmann::ordered_json phase_json(const project::PhaseProperties& phase) {
  const auto& k = phase.conductivity;
  return {{"conductivity", phase.anisotropic() ? nlohmann::ordered_json{k[0], k[1]} : nlohmann::ordered_json(k[0])},
          {"heat_capacity", phase.heat_capacity}};
}

}  // namespace

std::string calibrated_project_text(const std::string& text, const project::Project& fitted) {
  auto j = nlohmann::ordered_json::parse(text);
  const auto& s = fitted.soil;
  j["soil"] = {{"name", s.name + " (calibrated)"},   {"density", s.density},
               {"unfrozen", phase_json(s.unfrozen)}, {"frozen", phase_json(s.frozen)},
               {"latent_heat", s.latent_heat},       {"freezing_point", s.freezing_point},
               {"freezing_range", s.freezing_range}};
  j["domain"]["initial_temperature"] = fitted.domain.initial_temperature;
  if (fitted.domain.far_field_temperature && j["domain"].contains("far_field"))
    j["domain"]["far_field"]["temperature"] = *fitted.domain.far_field_temperature;
  if (fitted.groundwater && j.contains("groundwater")) {
    auto& g = j["groundwater"];
    g.erase("hydraulic_gradient");
    const auto& q = fitted.groundwater->darcy_flux;
    g["darcy_flux"] = {q[0] * project::seconds_per_day, q[1] * project::seconds_per_day};
    g["unit"] = "m/d";
  }
  j.erase("calibrate");
  return j.dump(2) + "\n";
}

}  // namespace frostwall::calibrate
