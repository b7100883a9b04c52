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
      range_per_H_l_(range_ > 0.0 ? range_ / H_l_ : 0.0),
      geometric_(soil.geometric_conductivity),
      rho_cs_sensible_(rho_cs_) {
  if (soil.freezing_curve.smooth()) tabulate(soil);
}

// H(T) on a fine grid in T from the bottom to the onset (trapezoidal
// sensible heat, exact latent heat), then T and f at equal steps of H by
// linear interpolation in that grid.
void PhaseChangeLaw::tabulate(const project::Soil& soil) {
  const auto& curve = soil.freezing_curve;
  Tf_ = curve.onset(soil.freezing_point);
  Ts_ = curve.bottom(soil.freezing_point);
  range_ = Tf_ - Ts_;
  constexpr int fine = 40000;
  const double dT = range_ / fine;
  std::vector<double> T(fine + 1), f(fine + 1), H(fine + 1);
  auto capacity = [&](double fi) { return rho_cs_ + fi * (rho_cl_ - rho_cs_); };
  for (int k = 0; k <= fine; ++k) {
    T[k] = Ts_ + k * dT;
    f[k] = curve.liquid_fraction(T[k], soil.freezing_point);
  }
  f[fine] = 1.0;
  H[0] = 0.0;
  for (int k = 1; k <= fine; ++k)
    H[k] = H[k - 1] + 0.5 * (capacity(f[k - 1]) + capacity(f[k])) * dT + rho_L_ * (f[k] - f[k - 1]);
  H_l_ = H[fine];
  f_bottom_ = f[0];
  // Below the bottom: the apparent capacity there (sensible and latent).
  rho_cs_ = capacity(f[0]) + rho_L_ * (f[1] - f[0]) / dT;
  inv_rho_cs_ = 1.0 / rho_cs_;
  inv_H_l_ = 1.0 / H_l_;
  segments_ = 4096;
  inv_step_ = segments_ / H_l_;
  auto table = std::make_shared<std::vector<double>>(2 * (segments_ + 1));
  auto& column = *table;
  int k = 0;
  for (int s = 0; s <= segments_; ++s) {
    const double Hs = H_l_ * s / segments_;
    while (k < fine - 1 && H[k + 1] < Hs) ++k;
    const double w = H[k + 1] > H[k] ? std::clamp((Hs - H[k]) / (H[k + 1] - H[k]), 0.0, 1.0) : 0.0;
    column[s] = T[k] + w * (T[k + 1] - T[k]);
    column[segments_ + 1 + s] = f[k] + w * (f[k + 1] - f[k]);
  }
  table_ = table;
  table_T_ = column.data();
  table_f_ = column.data() + segments_ + 1;
  // Where half the water is ice (f = 1/2; the loader keeps f_bottom below it).
  int h = 0;
  while (h < fine && f[h] < 0.5) ++h;
  H_half_ = h == 0 ? 0.0 : H[h - 1] + (0.5 - f[h - 1]) / (f[h] - f[h - 1]) * (H[h] - H[h - 1]);
  inv_left_ = 1.0 / (H_l_ - H_half_);
}

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
  if (table_T_) {  // T rises with H along the table
    const int k = static_cast<int>(std::upper_bound(table_T_, table_T_ + segments_ + 1, T) - table_T_) - 1;
    const int s = std::clamp(k, 0, segments_ - 1);
    const double dT = table_T_[s + 1] - table_T_[s];
    const double w = dT > 0.0 ? (T - table_T_[s]) / dT : 0.0;
    return (s + w) / inv_step_;
  }
  // Inside the range (or exactly at Tf when isothermal: taken as unfrozen,
  // the state of ground before any heat is drawn).
  return range_ > 0.0 ? H_l_ * (T - Ts_) / range_ : H_l_;
}

double PhaseChangeLaw::temperature_slope(double H, double direction) const {
  const double mushy = range_ > 0.0 ? range_ / H_l_ : 0.0;
  if (H < 0.0 || (H == 0.0 && direction < 0.0)) return 1.0 / rho_cs_;
  if (H > H_l_ || (H == H_l_ && direction > 0.0)) return 1.0 / rho_cl_;
  if (table_T_) {  // the table's segment on the side H moves into
    const double x = H * inv_step_;
    int s = static_cast<int>(x);
    if (direction < 0.0 && x == s) --s;
    s = std::clamp(s, 0, segments_ - 1);
    return (table_T_[s + 1] - table_T_[s]) * inv_step_;
  }
  return mushy;
}

bool PhaseChangeLaw::anisotropic() const { return k_frozen_[0] != k_frozen_[1] || k_unfrozen_[0] != k_unfrozen_[1]; }

double PhaseChangeLaw::max_diffusivity() const {
  double a = 0.0;
  for (int d = 0; d < 2; ++d) a = std::max({a, k_frozen_[d] / rho_cs_sensible_, k_unfrozen_[d] / rho_cl_});
  return a;
}

}  // namespace frostwall::thermal
