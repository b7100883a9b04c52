#include "thermal/heat_advection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "particles/pair_gradient.hpp"

namespace frostwall::thermal {

HeatAdvection::HeatAdvection(double water_heat_capacity, std::vector<double> pair_flux, AdvectionScheme scheme)
    : rho_c_w_(water_heat_capacity), flux_(std::move(pair_flux)), scheme_(scheme) {}

double HeatAdvection::stable_step(const ThermalModel& model) const {
  if (stable_ >= 0.0) return stable_;  // fixed until the fluxes change
  if (scheme_ == AdvectionScheme::implicit || scheme_ == AdvectionScheme::coupled)
    return stable_ = std::numeric_limits<double>::infinity();
  const auto& P = model.pairs();
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.n_free; ++i) {
    double inflow = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) inflow += std::max(0.0, -flux_[e]);
    if (inflow > 0.0)
      step = std::min(step, model.volume()[i] * model.law_of(i).smallest_heat_capacity() / (rho_c_w_ * inflow));
  }
  stable_ = scheme_ == AdvectionScheme::limited ? 0.5 * step : step;
  return stable_;
}

double HeatAdvection::limited_correction(const particles::PairWeights& P, std::size_t u, std::size_t e,
                                         double jump) const {
  if (jump == 0.0) return 0.0;
  const double r = 2.0 * (gradient_[2 * u] * P.vector[2 * e] + gradient_[2 * u + 1] * P.vector[2 * e + 1]) / jump - 1.0;
  return 0.5 * (r + std::abs(r)) / (1.0 + std::abs(r)) * jump;  // van Leer's phi(r) (T_d - T_u) / 2
}

void HeatAdvection::rate(const ThermalModel& model, double t, std::vector<double>& rate,
                         std::vector<double>& boundary_heat) const {
  const auto& P = model.pairs();
  if (flux_.size() != P.pairs()) throw std::logic_error("HeatAdvection: one flux per pair expected");
  // The implicit scheme steps its own faces; the coupled one leaves across
  // a wall at the particle's temperature (upwind, so monotone at any step).
  const bool limited = (scheme_ == AdvectionScheme::limited || scheme_ == AdvectionScheme::coupled) && !held_;
  const bool leave_upwind = scheme_ == AdvectionScheme::coupled;
  if (limited) particles::pair_gradient(P, model.temperature(), gradient_);
  const auto& T = model.temperature();
  const auto& boundary = model.boundary_ids();
  rate.assign(P.n_free, 0.0);
  boundary_heat.assign(model.boundaries().size(), 0.0);
  std::vector<double> wall(model.boundaries().size());
  for (std::size_t b = 0; b < wall.size(); ++b) wall[b] = model.boundaries()[b].temperature.at(t);
  // Each pair once: between free particles from its upstream end (Q > 0
  // in that row), to a fixed particle in the free particle's row.
  for (std::size_t i = 0; i < P.n_free; ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const double Q = flux_[e];
      const std::uint32_t j = P.column[e];
      const bool fixed = j >= P.n_free;
      if (fixed) {  // across the wall, at the wall's temperature (an insulated wall has none: upwind)
        if (Q == 0.0) continue;
        const std::size_t b = std::size_t(boundary[j]);
        const bool insulated = model.boundaries()[b].insulated;
        const double heat = rho_c_w_ * Q * (Q > 0.0 && (leave_upwind || insulated) ? T[i] : insulated ? T[j] : wall[b]);
        rate[i] -= heat;
        boundary_heat[b] -= heat;
      } else if (Q > 0.0) {
        const double face = T[i] + (limited ? limited_correction(P, i, e, T[j] - T[i]) : 0.0);
        const double heat = rho_c_w_ * Q * face;
        rate[i] -= heat;
        rate[j] += heat;
      }
    }
  if (held_)
    for (std::size_t i = 0; i < P.n_free; ++i) rate[i] += correction_[i];
}

void HeatAdvection::hold_limiter(const ThermalModel& model) {
  const auto& P = model.pairs();
  held_ = false;
  if (scheme_ != AdvectionScheme::coupled && scheme_ != AdvectionScheme::limited) return;
  particles::pair_gradient(P, model.temperature(), gradient_);
  const auto& T = model.temperature();
  correction_.assign(P.n_free, 0.0);
  for (std::size_t i = 0; i < P.n_free; ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const double Q = flux_[e];
      const std::uint32_t j = P.column[e];
      if (j >= P.n_free || Q <= 0.0) continue;
      const double heat = rho_c_w_ * Q * limited_correction(P, i, e, T[j] - T[i]);
      correction_[i] -= heat;
      correction_[j] += heat;
    }
  held_ = true;
}

std::vector<double> HeatAdvection::advance(ThermalModel& model, double t, double dt) {
  if (scheme_ == AdvectionScheme::implicit) return advance_implicit(model, t, dt);
  if (scheme_ == AdvectionScheme::coupled) return std::vector<double>(model.boundaries().size(), 0.0);
  std::vector<double> carried(model.boundaries().size(), 0.0);
  const double stable = stable_step(model);
  const long steps = std::isfinite(stable) ? std::max(1L, long(std::ceil(dt / stable - 1e-12))) : 1L;
  const double h = dt / double(steps);
  const auto& H = model.enthalpy();
  const auto& V = model.volume();
  for (long s = 0; s < steps; ++s) {
    // SSP Runge-Kutta 2: two Euler steps, then the mean with the start;
    // each stage monotone, so the step is.
    start_.assign(H.begin(), H.begin() + long(model.free_count()));
    const double t0 = t + double(s) * h;
    rate(model, t0, rate_, heat_);
    for (std::size_t b = 0; b < carried.size(); ++b) carried[b] += 0.5 * h * heat_[b];
    model.update_free([&](std::size_t i) { return H[i] + h * rate_[i] / V[i]; });
    rate(model, t0 + h, rate_, heat_);
    for (std::size_t b = 0; b < carried.size(); ++b) carried[b] += 0.5 * h * heat_[b];
    model.update_free([&](std::size_t i) { return 0.5 * (start_[i] + H[i] + h * rate_[i] / V[i]); });
  }
  return carried;
}

}  // namespace frostwall::thermal
