#include "thermal/phase_change.hpp"

#include <algorithm>

namespace frostwall::thermal {

PhaseChangeLaw::PhaseChangeLaw(const project::Soil& soil)
    : Tf_(soil.freezing_point),
      Ts_(soil.freezing_point - soil.freezing_range),
      range_(soil.freezing_range),
      rho_cs_(soil.density * soil.frozen.heat_capacity),
      rho_cl_(soil.density * soil.unfrozen.heat_capacity),
      rho_L_(soil.density * soil.latent_heat),
      H_l_(rho_L_ + 0.5 * (rho_cs_ + rho_cl_) * soil.freezing_range),
      k_frozen_(soil.frozen.conductivity),
      k_unfrozen_(soil.unfrozen.conductivity),
      inv_rho_cs_(1.0 / rho_cs_),
      inv_rho_cl_(1.0 / rho_cl_),
      inv_H_l_(H_l_ > 0.0 ? 1.0 / H_l_ : 0.0),
      range_per_H_l_(range_ > 0.0 ? range_ / H_l_ : 0.0) {}

PhaseChangeLaw pore_water_law(const project::PoreFluid& fluid) {
  project::Soil water;
  water.name = "pore water";
  water.density = fluid.water_density;
  water.unfrozen.conductivity = {fluid.water_conductivity, fluid.water_conductivity};
  water.unfrozen.heat_capacity = fluid.water_heat_capacity;
  water.frozen.conductivity = {fluid.ice_conductivity, fluid.ice_conductivity};
  water.frozen.heat_capacity = fluid.ice_heat_capacity;  // per kg: the water's mass freezes
  water.latent_heat = fluid.latent_heat;
  water.freezing_point = fluid.freezing_point;
  return PhaseChangeLaw(water);
}

double PhaseChangeLaw::enthalpy(double T) const {
  if (T < Ts_) return rho_cs_ * (T - Ts_);
  if (T > Tf_) return H_l_ + rho_cl_ * (T - Tf_);
  // Inside the range (or exactly at Tf when isothermal: taken as unfrozen,
  // the state of ground before any heat is drawn).
  return range_ > 0.0 ? H_l_ * (T - Ts_) / range_ : H_l_;
}

double PhaseChangeLaw::temperature_slope(double H, double direction) const {
  const double mushy = range_ > 0.0 ? range_ / H_l_ : 0.0;
  if (H < 0.0 || (H == 0.0 && direction < 0.0)) return 1.0 / rho_cs_;
  if (H > H_l_ || (H == H_l_ && direction > 0.0)) return 1.0 / rho_cl_;
  return mushy;
}

bool PhaseChangeLaw::anisotropic() const { return k_frozen_[0] != k_frozen_[1] || k_unfrozen_[0] != k_unfrozen_[1]; }

double PhaseChangeLaw::max_diffusivity() const {
  double a = 0.0;
  for (int d = 0; d < 2; ++d) a = std::max({a, k_frozen_[d] / rho_cs_, k_unfrozen_[d] / rho_cl_});
  return a;
}

}  // namespace frostwall::thermal
