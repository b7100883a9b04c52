// The heat that flowing groundwater carries, rho_w c_w div(q T), on the
// conduction pairs with the Darcy solver's pair fluxes Q_e (i to j, m^2/s
// per metre of depth; porous_flow/darcy_cloud.hpp). Pair e carries
// rho_w c_w Q_e T_up out of i and into j, with T_up the upstream
// particle's temperature (first-order upwind):
//  - conservative: each pair's heat leaves one particle and enters the
//    other (its mirror pair across a symmetry plane carries the opposite),
//    and what crosses into fixed particles is the heat carried out of the
//    ground, reported per boundary so the energy balance closes;
//  - monotone: the fluxes balance at every free particle, so an explicit
//    step is a weighted mean of the particle and its upstream neighbours
//    while dt <= the stable step; no new extremum near a sharp front.
// Because div q = 0, rho_w c_w q . grad T is the same term in advective form.
#pragma once

#include <vector>

#include "thermal/thermal_model.hpp"

namespace frostwall::thermal {

class HeatAdvection {
 public:
  // water_heat_capacity: rho_w c_w, J/(m3 K). pair_flux: Q_e for every
  // pair of model.pairs() (0 for pairs without flow).
  HeatAdvection(double water_heat_capacity, std::vector<double> pair_flux);

  void set_pair_flux(std::vector<double> pair_flux) { flux_ = std::move(pair_flux); }
  const std::vector<double>& pair_flux() const { return flux_; }

  // The largest explicit step that keeps the update monotone: for every
  // free particle, V_i C_min / (rho_w c_w sum of its inflows), C_min the
  // law's smaller sensible capacity (latent heat only slows a particle).
  double stable_step(const ThermalModel& model) const;

  // V_i dH_i/dt for the free particles (W per metre), and the heat the
  // water carries into the ground from each boundary (W per metre; out is
  // negative).
  void rate(const ThermalModel& model, std::vector<double>& rate, std::vector<double>& boundary_heat) const;

  // Advances the enthalpy by dt in as many equal stable steps as needed;
  // returns the heat carried in from each boundary, J per metre.
  std::vector<double> advance(ThermalModel& model, double dt);

 private:
  double rho_c_w_;
  std::vector<double> flux_;
  std::vector<double> rate_, heat_;
};

}  // namespace frostwall::thermal
