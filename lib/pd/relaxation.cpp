#include "pd/relaxation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "particles/parallel.hpp"

namespace frostwall::pd {

RelaxationResult relax(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT, double tolerance,
                       int max_iterations) {
  return relax_adjusting(solid, u, dT, tolerance, max_iterations, {}, 0);
}

RelaxationResult relax_adjusting(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT,
                                 double tolerance, int max_iterations, const std::function<bool()>& adjust,
                                 int check_every) {
  const std::size_t n = solid.size(), m = 2 * n;
  u.resize(m, 0.0);
  std::vector<double> lambda(m), v(m, 0.0), F(m), F_old(m), u_all, dT_all, thermal;
  solid.extend_temperature(dT, dT_all);
  if (solid.linear()) solid.thermal_force(dT_all, thermal);
  auto forces = [&](std::vector<double>& out) {
    solid.extend(u, u_all);
    if (solid.linear()) solid.forces_linear(u_all, thermal, out);
    else solid.forces_extended(u_all, dT_all, out);
  };
  // 1/4 of the Gershgorin sum (each bond's stiffness counted for both its
  // ends, so twice the particle's own sum), with a factor 2 of margin.
  // Particles the relaxation leaves (held, or without bonds) get 1/lambda = 0.
  std::vector<double> inv_lambda(m);
  for (std::size_t i = 0; i < n; ++i) {
    lambda[2 * i] = lambda[2 * i + 1] = 0.25 * 2.0 * 2.0 * solid.stiffness()[i];
    inv_lambda[2 * i] = inv_lambda[2 * i + 1] = solid.moves(i) ? 1.0 / lambda[2 * i] : 0.0;
  }
  RelaxationResult result;
  // The solid's changes; true when there were some (the thermal force,
  // which broken bonds no longer carry, is rebuilt).
  auto changed = [&] {
    if (!adjust || !adjust()) return false;
    if (solid.linear()) solid.thermal_force(dT_all, thermal);
    for (std::size_t i = 0; i < n; ++i)
      if (!solid.moves(i)) inv_lambda[2 * i] = inv_lambda[2 * i + 1] = 0.0;  // lost every bond
    return true;
  };
  forces(F);
  // A reference force: the stiffness times a strain of 1e-12 on a bond.
  double scale = 0.0;
  for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, solid.stiffness()[i]);
  const double horizon = solid.law().horizon;
  auto rms = [&](auto&& value) {
    return std::sqrt(particles::sum_over_particles(m, [&](std::size_t k) { return value(k) * value(k); }) / m);
  };
  if (rms([&](std::size_t k) { return inv_lambda[k] > 0.0 ? F[k] : 0.0; }) <= 1e-14 * scale * horizon && !changed()) {
    result.converged = true;
    return result;
  }
  // Rigid groups (held particles that move together: a pore riding on
  // the plate) are one degree of freedom per axis each: the sum of their
  // members' forces over the sum of their lambdas.
  const auto& groups = solid.groups();
  std::vector<double> group_lambda(groups.size(), 0.0), vg(2 * groups.size(), 0.0);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (std::size_t i : groups[g]) group_lambda[g] += lambda[2 * i];
  double c = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    // First step: v(1/2) = F / (2 lambda).
    const double c_now = it == 0 ? 0.0 : c;
    particles::for_each_particle(m, [&](std::size_t k) {
      v[k] = it == 0 ? 0.5 * F[k] * inv_lambda[k] : ((2.0 - c_now) * v[k] + 2.0 * F[k] * inv_lambda[k]) / (2.0 + c_now);
      u[k] += v[k];
    });
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (group_lambda[g] == 0.0) continue;
      for (int d = 0; d < 2; ++d) {
        double Fg = 0.0;
        for (std::size_t i : groups[g]) Fg += F[2 * i + d];
        double& w = vg[2 * g + d];
        w = it == 0 ? 0.5 * Fg / group_lambda[g] : ((2.0 - c_now) * w + 2.0 * Fg / group_lambda[g]) / (2.0 + c_now);
        for (std::size_t i : groups[g]) u[2 * i + d] += w;
      }
    }
    F_old.swap(F);
    forces(F);
    // One pass: the damping's u.K u and u.u from the local stiffness of
    // this step, and the RMS of the increment and of the force.
    const auto sums = particles::sums_over_particles<4>(m, [&](std::size_t k, std::array<double, 4>& acc) {
      if (inv_lambda[k] == 0.0) return;
      const double uk2 = u[k] * u[k];
      acc[1] += uk2;
      if (v[k] != 0.0) acc[0] += uk2 * (-(F[k] - F_old[k]) * inv_lambda[k] / v[k]);
      acc[2] += v[k] * v[k];
      acc[3] += F[k] * F[k];
    });
    c = sums[0] > 0.0 && sums[1] > 0.0 ? std::min(2.0 * std::sqrt(sums[0] / sums[1]), 1.99) : 0.0;
    result.iterations = it + 1;
    const double du = std::sqrt(sums[2] / m), uu = std::sqrt(sums[1] / m), ff = std::sqrt(sums[3] / m);
    result.increment = uu > 0.0 ? du / uu : 0.0;
    const bool still = du <= tolerance * uu || ff <= 1e-14 * scale * horizon;
    if ((still || (check_every > 0 && (it + 1) % check_every == 0)) && changed()) {
      forces(F);  // the same u, fewer bonds
      continue;
    }
    if (still) {
      result.converged = true;
      break;
    }
  }
  return result;
}

}  // namespace frostwall::pd
