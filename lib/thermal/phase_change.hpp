// The phase-change law of a soil in enthalpy form (physics.md section 1).
// Volumetric enthalpy H is zero at the fully frozen end of freezing,
// T_s = Tf - range; latent heat rho*L is released linearly in temperature
// over [T_s, Tf] (isothermally at Tf when range = 0):
//     H < 0            frozen:   T = T_s + H / (rho Cs)
//     0 <= H <= H_l    freezing: T = T_s + range * H / H_l,  f = H / H_l
//     H > H_l          unfrozen: T = Tf + (H - H_l) / (rho Cl)
// with H_l = rho (L + Cm range), Cm = (Cs + Cl)/2 the sensible capacity
// inside the range. The SPH paper's per-particle latent-heat accumulator is
// this bookkeeping with range = 0.
//
// A smooth curve (exponential or power, project::FreezingCurve) keeps
// the three pieces with Tf its onset and T_s its table's bottom; in between
// T and f are tabulated at equal steps of H (H from the exact latent heat
// rho L (1 - f) and the sensible capacity (1 - f) rho Cs + f rho Cl
// integrated along the curve). Below T_s the share f(T_s) stays liquid and
// the capacity is the curve's apparent capacity there.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

#include "project/project.hpp"

namespace frostwall::thermal {

class PhaseChangeLaw {
 public:
  explicit PhaseChangeLaw(const project::Soil& soil);

  double enthalpy(double T) const;
  // Inline: called for every particle at every stage.
  // (Multiplications by stored inverses: a division per particle and stage
  // was a tenth of a super-time-step's cost.)
  double temperature(double H) const {
    if (H < 0.0) return Ts_ + H * inv_rho_cs_;
    if (H > H_l_) return Tf_ + (H - H_l_) * inv_rho_cl_;
    if (table_T_) return tabulated(table_T_, H);
    return Ts_ + H * range_per_H_l_;
  }
  double liquid_fraction(double H) const {
    if (table_f_) return H <= 0.0 ? f_bottom_ : H >= H_l_ ? 1.0 : tabulated(table_f_, H);
    if (H_l_ <= 0.0) return H > 0.0 ? 1.0 : 0.0;  // no latent heat, no range
    return std::clamp(H * inv_H_l_, 0.0, 1.0);
  }
  // Conductivity along axis d: linear in liquid fraction between the frozen
  // and the unfrozen value (a freezing particle is a frozen and an unfrozen
  // share side by side), or geometric (constituents mixed geometrically).
  double conductivity(double f, int axis) const {
    if (geometric_) return k_frozen_[axis] * std::pow(k_unfrozen_[axis] / k_frozen_[axis], f);
    return k_frozen_[axis] + f * (k_unfrozen_[axis] - k_frozen_[axis]);
  }
  // A smooth freezing curve (exponential or power) is tabulated.
  bool tabulated() const { return table_T_ != nullptr; }
  bool anisotropic() const;
  double max_diffusivity() const;  // m2/s, over both phases and axes
  double freezing_point() const { return Tf_; }
  // H at the unfrozen end of freezing (the law's kinks are at 0 and here).
  double latent_enthalpy() const { return H_l_; }
  // dT/dH on the side of H that a change of sign `direction` moves into:
  // 0 inside an isothermal change, so an implicit step knows T is pinned.
  double temperature_slope(double H, double direction) const;
  double latent_heat_volumetric() const { return rho_L_; }
  // The smaller sensible heat capacity, frozen or unfrozen, J/(m3 K): the
  // least heat a particle needs per kelvin (latent heat only adds to it).
  double smallest_heat_capacity() const { return std::min(rho_cs_sensible_, rho_cl_); }
  // H / H_l unclamped: the share of its latent heat a particle still holds
  // (1 at the start of freezing, 0 fully frozen, below 0 colder). Closure
  // follows it through 0 (post/closure.hpp). Without latent heat, H over
  // the heat of 1 K of frozen ground: 0 at the freezing point all the same.
  // With a smooth curve, (H - H_half) / (H_l - H_half): ground counts as
  // frozen once half its pore water is ice (H_half where f = 1/2).
  double latent_left(double H) const {
    if (table_T_) return (H - H_half_) * inv_left_;
    return H_l_ > 0.0 ? H * inv_H_l_ : H * inv_rho_cs_;
  }
  // The temperature at which ground counts as frozen: Tf, a
  // linear range's cold end, or where a smooth curve leaves half the water
  // liquid (where latent_left passes 0).
  double frozen_temperature() const { return table_T_ ? temperature(H_half_) : Ts_; }

 private:
  double tabulated(const double* column, double H) const {
    const double x = H * inv_step_;
    const int k = std::min(static_cast<int>(x), segments_ - 1);
    return column[k] + (x - k) * (column[k + 1] - column[k]);
  }
  void tabulate(const project::Soil& soil);
  double Tf_, Ts_, range_;
  double rho_cs_, rho_cl_, rho_L_, H_l_;
  std::array<double, 2> k_frozen_, k_unfrozen_;
  double inv_rho_cs_, inv_rho_cl_, inv_H_l_, range_per_H_l_;
  bool geometric_ = false;
  double rho_cs_sensible_;  // the frozen capacity (rho_cs_ is the apparent one below a table)
  // A smooth curve's table: T and f at H = k H_l / segments_, k = 0..segments_.
  std::shared_ptr<const std::vector<double>> table_;
  const double* table_T_ = nullptr;
  const double* table_f_ = nullptr;
  int segments_ = 0;
  double inv_step_ = 0.0, f_bottom_ = 0.0, H_half_ = 0.0, inv_left_ = 0.0;
};

// The law of pore water (a porous plate's pores), per unit volume of the
// pore: latent heat rho_w L, liquid rho_w C_w, ice rho_w C_i. The pore's
// mass freezes, so the ice's capacity is that mass's (rho_i C_i over the
// 1000/920 = 8.7 % larger volume the ice would take free); the particles
// keep their volume, the expansion is the mechanics' concern.
PhaseChangeLaw pore_water_law(const project::PoreFluid& fluid);

}  // namespace frostwall::thermal
