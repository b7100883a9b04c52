#include "groundwater/permeability_law.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::groundwater {

double PermeabilityLaw::relative(double liquid_fraction) const {
  const double f = std::clamp(liquid_fraction, 0.0, 1.0);
  double k = 1.0;
  switch (model) {
    case PermeabilityModel::impedance: k = std::pow(10.0, -impedance * (1.0 - f)); break;
    case PermeabilityModel::kozeny_carman: {
      const auto carman = [](double n) { return n * n * n / ((1.0 - n) * (1.0 - n)); };
      k = carman(porosity * f) / carman(porosity);
      break;
    }
    case PermeabilityModel::threshold: k = f >= threshold_liquid_fraction ? 1.0 : 0.0; break;
    case PermeabilityModel::constant: break;
  }
  return std::max(k, floor);
}

std::string PermeabilityLaw::name() const {
  switch (model) {
    case PermeabilityModel::impedance: return "impedance";
    case PermeabilityModel::kozeny_carman: return "kozeny_carman";
    case PermeabilityModel::threshold: return "threshold";
    case PermeabilityModel::constant: return "constant";
  }
  return "?";
}

PermeabilityLaw permeability_law(const project::PermeabilitySettings& s) { return {s}; }

bool permeability_model_from_name(const std::string& name, PermeabilityModel& model) {
  for (auto m : {PermeabilityModel::impedance, PermeabilityModel::kozeny_carman, PermeabilityModel::threshold,
                 PermeabilityModel::constant})
    if (PermeabilityLaw{m}.name() == name) {
      model = m;
      return true;
    }
  return false;
}

}  // namespace frostwall::groundwater
