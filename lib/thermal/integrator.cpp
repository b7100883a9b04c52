#include "thermal/integrator.hpp"

#include "particles/parallel.hpp"

namespace frostwall::thermal {

std::vector<double> ExplicitEuler::advance(ThermalModel& model, double t, double dt) {
  model.apply_boundaries(t);
  model.conduction_rate(rate_);
  std::vector<double> heat = model.boundary_heat_rate();
  for (double& q : heat) q *= dt;
  const auto& H = model.enthalpy();
  model.update_free([&](std::size_t i) { return H[i] + dt * rate_[i]; });
  return heat;
}

}  // namespace frostwall::thermal
