// HeatAdvection's implicit scheme (heat_advection.hpp): upwind faces in
// the theta scheme, each pair's heat from its upstream end u,
//   rho_w c_w Q (theta_u T_u' + (1 - theta_u) T_u)   (' the new time),
// theta_u = max(1/2, 1 - 1/Co_u), Co_u = dt rho_w c_w out_u / (V_u C_min):
// Crank-Nicolson where the water moves less than two particles' heat a
// step, leaning to backward Euler beyond, just enough that every weight
// stays positive (monotone at any step). Water leaving across a wall
// carries the particle's temperature. Solved in one sweep downstream.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "thermal/heat_advection.hpp"

namespace frostwall::thermal {

namespace {

// The H that solves V H + c T(H) = R, c >= 0: T(H) is linear on each of
// the law's three pieces (frozen, freezing, unfrozen; a smooth curve's on
// each segment of its table) and the left side rises with H, so the root is
// found on the piece where it changes sign (by bisection on a table).
double solve_particle(const PhaseChangeLaw& law, double V, double c, double R) {
  const double Hl = law.latent_enthalpy();
  auto g = [&](double H) { return V * H + c * law.temperature(H) - R; };
  const double g0 = g(0.0);
  if (g0 >= 0.0) {  // frozen (or at the start of freezing)
    const double slope = law.temperature_slope(0.0, -1.0);
    return -g0 / (V + c * slope);
  }
  const double gl = g(Hl);
  if (gl >= 0.0 && law.tabulated()) {  // a smooth curve: g is linear on each segment of its table
    double lo = 0.0, hi = Hl, g_lo = g0, g_hi = gl;
    for (int it = 0; it < 60 && hi - lo > 1e-12 * Hl; ++it) {
      const double mid = 0.5 * (lo + hi), gm = g(mid);
      (gm < 0.0 ? lo : hi) = mid;
      (gm < 0.0 ? g_lo : g_hi) = gm;
    }
    return g_hi > g_lo ? lo + (hi - lo) * (-g_lo) / (g_hi - g_lo) : lo;
  }
  if (gl >= 0.0) return Hl > 0.0 ? Hl * (-g0) / (gl - g0) : 0.0;  // freezing: g linear between the kinks
  const double slope = law.temperature_slope(Hl, 1.0);
  return Hl - gl / (V + c * slope);  // unfrozen
}

}  // namespace

void HeatAdvection::find_downstream_order(const ThermalModel& model) {
  const auto& P = model.pairs();
  const std::size_t n = P.n_free;
  // Inflows per particle: the pairs of other rows whose water enters it.
  inflow_start_.assign(n + 1, 0);
  row_of_pair_.resize(P.pairs());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      row_of_pair_[e] = std::uint32_t(i);
      const std::size_t j = P.column[e];
      if (flux_[e] > 0.0 && j < n && j != i) ++inflow_start_[j + 1];
    }
  for (std::size_t i = 0; i < n; ++i) inflow_start_[i + 1] += inflow_start_[i];
  inflow_pair_.resize(inflow_start_[n]);
  std::vector<std::uint32_t> fill(inflow_start_.begin(), inflow_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const std::size_t j = P.column[e];
      if (flux_[e] > 0.0 && j < n && j != i) inflow_pair_[fill[j]++] = std::uint32_t(e);
    }
  // Kahn's topological order: a particle is ready once every particle
  // feeding it is. The flux follows the potential, so there is no cycle.
  std::vector<std::uint32_t> waiting(n);
  order_.clear();
  order_.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    waiting[i] = inflow_start_[i + 1] - inflow_start_[i];
    if (waiting[i] == 0) order_.push_back(std::uint32_t(i));
  }
  for (std::size_t k = 0; k < order_.size(); ++k) {
    const std::size_t i = order_[k];
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const std::size_t j = P.column[e];
      if (flux_[e] > 0.0 && j < n && j != i && --waiting[j] == 0) order_.push_back(std::uint32_t(j));
    }
  }
  if (order_.size() != n) throw std::logic_error("HeatAdvection: the pair fluxes circulate (not a potential flow)");
}

std::vector<double> HeatAdvection::advance_implicit(ThermalModel& model, double t, double dt) {
  const auto& P = model.pairs();
  if (flux_.size() != P.pairs()) throw std::logic_error("HeatAdvection: one flux per pair expected");
  if (order_.empty()) find_downstream_order(model);
  const std::size_t n = P.n_free;
  const auto& H = model.enthalpy();
  const auto& T = model.temperature();
  const auto& V = model.volume();
  const auto& boundary = model.boundary_ids();
  std::vector<double> wall(model.boundaries().size()), carried(wall.size(), 0.0);
  for (std::size_t b = 0; b < wall.size(); ++b) wall[b] = model.boundaries()[b].temperature.at(t + dt);
  // Reused buffers: start_ holds the new enthalpies, rate_ the new
  // temperatures, filled in downstream order.
  start_.assign(H.begin(), H.begin() + long(n));
  rate_.assign(n, 0.0);
  theta_.assign(n, 1.0);
  const double w = dt * rho_c_w_;
  for (const std::uint32_t i : order_) {
    double out = 0.0, out_wall = 0.0, in = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const double Q = flux_[e];
      const std::size_t j = P.column[e];
      if (j >= n) {  // in across a wall at its temperature (insulated: its particle's); out at the particle's
        if (Q < 0.0) {
          const std::size_t b = std::size_t(boundary[j]);
          const double T_in = model.boundaries()[b].insulated ? model.temperature()[j] : wall[b];
          in -= Q * T_in;
          carried[b] -= w * Q * T_in;
        } else if (Q > 0.0) out += Q, out_wall += Q;
      } else if (Q > 0.0 && j != i) out += Q;
    }
    // theta: Crank-Nicolson (second order) where the water moves less than
    // a particle's heat per step, leaning to backward Euler beyond, just
    // enough to keep every weight positive (monotone).
    const auto& law = model.law_of(i);
    const double courant = w * out / (V[i] * law.smallest_heat_capacity());
    const double theta = std::max(0.5, 1.0 - 1.0 / std::max(courant, 1e-300));
    theta_[i] = theta;
    for (std::size_t k = inflow_start_[i]; k < inflow_start_[i + 1]; ++k) {
      const std::uint32_t e = inflow_pair_[k];
      const std::uint32_t u = row_of_pair_[e];
      in += flux_[e] * (theta_[u] * rate_[u] + (1.0 - theta_[u]) * T[u]);
    }
    if (out == 0.0 && in == 0.0) {
      rate_[i] = T[i];
      continue;
    }
    rate_[i] = law.temperature(
        solve_particle(law, V[i], w * out * theta, V[i] * H[i] + w * (in - (1.0 - theta) * out * T[i])));
    // The enthalpy from the balance with the temperature the particle
    // passes on, so the heat is conserved to round-off, not to the root's.
    start_[i] = H[i] + w * (in - out * (theta * rate_[i] + (1.0 - theta) * T[i])) / V[i];
    if (out_wall > 0.0)
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e)
        if (P.column[e] >= n && flux_[e] > 0.0)
          carried[std::size_t(boundary[P.column[e]])] -= w * flux_[e] * (theta * rate_[i] + (1.0 - theta) * T[i]);
  }
  model.update_free([&](std::size_t i) { return start_[i]; });
  return carried;
}

}  // namespace frostwall::thermal
