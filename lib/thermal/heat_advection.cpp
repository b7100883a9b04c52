#include "thermal/heat_advection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace frostwall::thermal {

HeatAdvection::HeatAdvection(double water_heat_capacity, std::vector<double> pair_flux)
    : rho_c_w_(water_heat_capacity), flux_(std::move(pair_flux)) {}

double HeatAdvection::stable_step(const ThermalModel& model) const {
  const auto& P = model.pairs();
  double step = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.n_free; ++i) {
    double inflow = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) inflow += std::max(0.0, -flux_[e]);
    if (inflow > 0.0) step = std::min(step, model.volume()[i] * model.law_of(i).smallest_heat_capacity() / (rho_c_w_ * inflow));
  }
  return step;
}

void HeatAdvection::rate(const ThermalModel& model, std::vector<double>& rate, std::vector<double>& boundary_heat) const {
  const auto& P = model.pairs();
  if (flux_.size() != P.pairs()) throw std::logic_error("HeatAdvection: one flux per pair expected");
  const auto& T = model.temperature();
  rate.assign(P.n_free, 0.0);
  boundary_heat.assign(model.boundaries().size(), 0.0);
  const auto& boundary = model.boundary_ids();
  particles::for_each_particle(P.n_free, [&](std::size_t i) {
    double out = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const double Q = flux_[e];
      out += Q * (Q > 0.0 ? T[i] : T[P.column[e]]);
    }
    rate[i] = -rho_c_w_ * out;
  });
  // What crosses into fixed particles enters or leaves the ground there.
  for (std::size_t i = 0; i < P.n_free; ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e)
      if (const std::uint32_t j = P.column[e]; j >= P.n_free && flux_[e] != 0.0)
        boundary_heat[std::size_t(boundary[j])] -= rho_c_w_ * flux_[e] * (flux_[e] > 0.0 ? T[i] : T[j]);
}

std::vector<double> HeatAdvection::advance(ThermalModel& model, double dt) {
  std::vector<double> carried(model.boundaries().size(), 0.0);
  const double stable = stable_step(model);
  const long steps = std::isfinite(stable) ? std::max(1L, long(std::ceil(dt / stable - 1e-12))) : 1L;
  const double h = dt / double(steps);
  for (long s = 0; s < steps; ++s) {
    rate(model, rate_, heat_);
    const auto& H = model.enthalpy();
    const auto& V = model.volume();
    model.update_free([&](std::size_t i) { return H[i] + h * rate_[i] / V[i]; });
    for (std::size_t b = 0; b < carried.size(); ++b) carried[b] += h * heat_[b];
  }
  return carried;
}

}  // namespace frostwall::thermal
