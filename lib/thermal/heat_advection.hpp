// The heat that flowing groundwater carries, rho_w c_w div(q T), on the
// conduction pairs with the Darcy solver's pair fluxes Q_e (i to j, m^2/s
// per metre of depth; groundwater/darcy_cloud.hpp). Each pair's heat,
// rho_w c_w |Q_e| T_face, is computed once, from its upstream end u to its
// downstream end d, and taken from one and given to the other:
//  - upwind: T_face = T_u (first order);
//  - limited (default when the pairs carry their vectors): T_face =
//    T_u + phi(r) (T_d - T_u) / 2, van Leer's limiter phi on the ratio
//    r = 2 grad T_u . (x_d - x_u) / (T_d - T_u) - 1, grad T_u a least-
//    squares fit over u's pairs: central (second order) where T is smooth,
//    upwind at a sharp front.
// A pair to a fixed particle crosses its boundary's wall (a pipe, the far
// field, a face), where the temperature is the wall's: water crossing
// there, in or out, carries the wall temperature at that time (a fixed
// particle beyond the wall holds an extrapolated value instead).
// Time: SSP Runge-Kutta 2, sub-stepped (upwind, limited); or
//  - implicit: upwind faces in a theta scheme (Crank-Nicolson where the
//    step is short, backward Euler where it is long), any step. Water flows
//    down the potential, so in order of falling potential every particle's
//    upstream neighbours are already at the new time: one sweep solves the
//    whole system exactly (heat_advection_implicit.cpp). Conservative and
//    monotone at any step. Screening only: split from the conduction at
//    long steps, its steady balance of the two moves with the step (the
//    1-D test: 5 % off at Courant 1, 20 % at 10), and it is first order.
//  - coupled: limited faces in the conduction's own backward-Euler step
//    (thermal/backward_euler.hpp), one nonlinear system for both, so the
//    balance of the two does not move with the step; water leaving across
//    a wall carries the particle's temperature. advance() does nothing.
// Because div q = 0, rho_w c_w q . grad T is the same term in advective form.
#pragma once

#include <cstdint>
#include <vector>

#include "thermal/thermal_model.hpp"

namespace frostwall::thermal {

enum class AdvectionScheme { upwind, limited, implicit, coupled };

class HeatAdvection {
 public:
  // water_heat_capacity: rho_w c_w, J/(m3 K). pair_flux: Q_e for every
  // pair of model.pairs() (0 for pairs without flow). `limited` needs the
  // pairs' vectors (sph::LaplacianOptions::keep_vectors).
  HeatAdvection(double water_heat_capacity, std::vector<double> pair_flux,
                AdvectionScheme scheme = AdvectionScheme::limited);

  void set_pair_flux(std::vector<double> pair_flux) {
    flux_ = std::move(pair_flux);
    held_ = false;
    stable_ = -1.0;
    order_.clear();
  }
  AdvectionScheme scheme() const { return scheme_; }
  double water_heat_capacity() const { return rho_c_w_; }
  const std::vector<double>& pair_flux() const { return flux_; }

  // The largest explicit step that keeps the update monotone: for every
  // free particle, V_i C_min / (rho_w c_w sum of its inflows), C_min the
  // law's smaller sensible capacity (latent heat only slows a particle);
  // half that with the limiter (its face values reach twice as far);
  // unbounded for the implicit scheme.
  double stable_step(const ThermalModel& model) const;

  // V_i dH_i/dt for the free particles (W per metre; upwind for the
  // implicit scheme, whose steps do not use it), and the heat the
  // water carries into the ground from each boundary (W per metre; out is
  // negative).
  // (Wall temperatures at time t.)
  void rate(const ThermalModel& model, double t, std::vector<double>& rate, std::vector<double>& boundary_heat) const;

  // The coupled step's limiter, held: from now on rate() takes upwind
  // faces plus each pair's limited correction, rho_w c_w Q phi (T_d - T_u) / 2,
  // as it is at the model's present temperatures. The Newton matrix is the
  // upwind part, so with the correction held Newton converges as upwind
  // does (the limiter's own lag costs one iteration per digit otherwise).
  // The corrections are pair exchanges: the heat stays conserved.
  void hold_limiter(const ThermalModel& model);
  void release_limiter() { held_ = false; }

  // Advances the enthalpy from t by dt in as many equal stable steps as
  // needed; returns the heat carried in from each boundary, J per metre.
  std::vector<double> advance(ThermalModel& model, double t, double dt);

 private:
  // The limited face's step beyond the upstream temperature, phi(r) (T_d - T_u) / 2,
  // for pair e from its upstream end u (gradient_ filled).
  double limited_correction(const particles::PairWeights& P, std::size_t u, std::size_t e, double jump) const;
  // The implicit scheme's single backward-Euler step of dt.
  std::vector<double> advance_implicit(ThermalModel& model, double t, double dt);
  // The free particles upstream first, and per particle the pairs (in
  // their upstream ends' rows) whose water flows into it.
  void find_downstream_order(const ThermalModel& model);
  double rho_c_w_;
  std::vector<double> flux_;
  AdvectionScheme scheme_;
  mutable std::vector<double> gradient_;  // of T, 2 per free particle
  mutable double stable_ = -1.0;          // stable_step() for these fluxes (< 0: not yet found)
  bool held_ = false;                     // hold_limiter(): correction_ is added to upwind faces
  std::vector<double> correction_;        // per free particle, W per metre
  std::vector<double> rate_, heat_, start_;
  std::vector<double> theta_;
  std::vector<std::uint32_t> order_, inflow_start_, inflow_pair_, row_of_pair_;
};

}  // namespace frostwall::thermal
