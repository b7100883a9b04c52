#include "thermal/backward_euler.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>

#include "particles/parallel.hpp"
#include "thermal/ilu0.hpp"
#include "thermal/heat_advection.hpp"

namespace frostwall::thermal {

// The Newton matrix in temperature increments, one row per free particle:
//   (C_i/dt + sum_e a_e) dT_i - sum_{j free} a_e dT_j + sum_{j beyond a wall} a_e sum_m w_jm dT_m
// (a fixed particle beyond a wall follows the free ones through its
// extension T_j = 2 T_wall - sum_m w_jm T_m; one on a wall does not move),
// and the identity row for a pinned particle. The pattern is built once;
// each iteration only rewrites the values.
struct BackwardEuler::LinearSystem {
  using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  Matrix A;
  std::vector<int> diagonal;    // value index of (i, i)
  std::vector<int> pair_entry;  // per pair: value index of (i, j) for free j, else -1
  // Per row, the terms a fixed neighbour beyond a wall brings: (value index, pair, weight).
  std::vector<std::size_t> wall_start;
  std::vector<int> wall_entry;
  std::vector<std::size_t> wall_pair;
  std::vector<double> wall_weight;
  // ILU(0), factored every Newton iteration: kept from a step's first, it
  // took 21 times the iterations (a particle changing piece changes its
  // row's capacity by the latent heat's factor).
  Eigen::BiCGSTAB<Matrix, IncompleteLU0> solver;

  explicit LinearSystem(const ThermalModel& model) {
    const auto& P = model.pairs();
    const auto& W = model.beyond_wall();
    const std::size_t n = P.n_free;
    const bool extend = !W.row_start.empty();
    std::vector<Eigen::Triplet<double, int>> pattern;
    for (std::size_t i = 0; i < n; ++i) {
      pattern.emplace_back(i, i, 0.0);
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
        const std::uint32_t j = P.column[e];
        if (j < n) pattern.emplace_back(i, j, 0.0);
        else if (extend && !W.on_wall(j - n))
          for (std::size_t m = W.row_start[j - n]; m < W.row_start[j - n + 1]; ++m)
            pattern.emplace_back(i, W.column[m], 0.0);
      }
    }
    A.resize(static_cast<int>(n), static_cast<int>(n));
    A.setFromTriplets(pattern.begin(), pattern.end());
    A.makeCompressed();
    const int* outer = A.outerIndexPtr();
    const int* inner = A.innerIndexPtr();
    auto entry = [&](std::size_t i, std::uint32_t j) {
      const int* found = std::lower_bound(inner + outer[i], inner + outer[i + 1], static_cast<int>(j));
      return static_cast<int>(found - inner);
    };
    diagonal.resize(n);
    pair_entry.assign(P.pairs(), -1);
    wall_start.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
      diagonal[i] = entry(i, i);
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
        const std::uint32_t j = P.column[e];
        if (j < n) pair_entry[e] = entry(i, j);
        else if (extend && !W.on_wall(j - n))
          for (std::size_t m = W.row_start[j - n]; m < W.row_start[j - n + 1]; ++m) {
            wall_entry.push_back(entry(i, W.column[m]));
            wall_pair.push_back(e);
            wall_weight.push_back(W.weight[m]);
          }
      }
      wall_start[i + 1] = wall_entry.size();
    }
  }

  // Writes the matrix for the current coefficients; slope[i] = dT/dH
  // (0: pinned). With water, its upwind part: a particle's outflows on its
  // diagonal, its inflows from free particles off it (w = rho_w c_w).
  void assemble(const ThermalModel& model, const std::vector<double>& a, const std::vector<double>& slope, double dt,
                const HeatAdvection* water) {
    const std::vector<double>* flux = water ? &water->pair_flux() : nullptr;
    const double w = water ? water->water_heat_capacity() : 0.0;
    const auto& V = model.volume();
    const auto& P = model.pairs();
    double* value = A.valuePtr();
    const int* outer = A.outerIndexPtr();
    particles::for_each_particle(P.n_free, [&](std::size_t i) {
      std::fill(value + outer[i], value + outer[i + 1], 0.0);
      if (slope[i] == 0.0) {
        value[diagonal[i]] = 1.0;
        return;
      }
      double diag = 1.0 / (slope[i] * dt);
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
        diag += a[e];
        if (pair_entry[e] >= 0) value[pair_entry[e]] -= a[e];
      }
      for (std::size_t k = wall_start[i]; k < wall_start[i + 1]; ++k)
        value[wall_entry[k]] += a[wall_pair[k]] * wall_weight[k];
      if (flux)
        for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
          const double Q = (*flux)[e];
          if (P.column[e] == i) continue;  // to its own image: no net heat
          if (Q > 0.0) diag += w * Q / V[i];
          else if (Q < 0.0 && pair_entry[e] >= 0) value[pair_entry[e]] += w * Q / V[i];
        }
      value[diagonal[i]] += diag;
    });
  }
};

BackwardEuler::BackwardEuler(BackwardEulerSettings settings, double explicit_step)
    : settings_(settings),
      control_(settings.step_change, settings.first_step > 0.0 ? settings.first_step : 5.0 * explicit_step,
               settings.max_steps_explicit * explicit_step, settings.growth),
      max_step_(settings.max_steps_explicit * explicit_step) {}

BackwardEuler::~BackwardEuler() = default;

std::vector<double> BackwardEuler::advance(ThermalModel& model, double t, double dt) {
  const std::size_t n = model.free_count();
  if (!system_) system_ = std::make_unique<LinearSystem>(model);
  control_.remember(model);
  if (!try_step(model, t, dt)) {
    // Newton did not settle (many particles changing phase at once): two half steps.
    ++stats_.halvings;
    for (std::size_t i = 0; i < n; ++i) model.set_enthalpy(i, control_.before()[i]);
    auto heat = advance(model, t, 0.5 * dt);
    const auto second = advance(model, t + 0.5 * dt, 0.5 * dt);
    for (std::size_t b = 0; b < heat.size(); ++b) heat[b] += second[b];
    control_.shorten_to(0.5 * dt * settings_.growth);
    return heat;
  }
  ++stats_.steps;
  control_.adapt(model, dt);
  std::vector<double> heat = model.boundary_heat_rate();
  for (std::size_t b = 0; b < heat.size() && water_; ++b) heat[b] += water_heat_[b];  // at the converged state
  for (double& q : heat) q *= dt;
  return heat;
}

bool BackwardEuler::try_step(ThermalModel& model, double t, double dt) {
  const std::size_t n = model.free_count();
  const auto& P = model.pairs();
  const auto& W = model.beyond_wall();
  const double scale = ActivityStepControl::enthalpy_scale(model);
  const std::vector<double>& H_old = control_.before();
  std::vector<double> slope(n);
  residual_.resize(n);
  next_H_.resize(n);
  Eigen::VectorXd rhs(n), x(n);
  model.apply_boundaries(t + dt);
  for (int it = 0; it < settings_.max_newton; ++it) {
    const std::vector<double>& a_ = model.pair_coefficients();
    const auto& T = model.temperature();
    const auto& H = model.enthalpy();
    const auto& V = model.volume();
    if (water_ && it == 0) water_->release_limiter();
    if (water_ && settings_.settle_after > 0 && it == settings_.settle_after) {
      if (settled_) settled_(model);
      water_->hold_limiter(model);
    }
    if (water_) water_->rate(model, t + dt, water_rate_, water_heat_);
    const double worst = particles::max_over_particles(n, [&](std::size_t i) {
      double flow = water_ ? water_rate_[i] / V[i] : 0.0;
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) flow += a_[e] * (T[P.column[e]] - T[i]);
      residual_[i] = flow - (H[i] - H_old[i]) / dt;
      return std::abs(residual_[i]) * dt / scale;
    });
    const double ntol = settings_.newton_tolerance;
    if (worst <= ntol) return true;
    ++stats_.newton_iterations;

    particles::for_each_particle(n, [&](std::size_t i) {
      slope[i] = model.law_of(i).temperature_slope(H[i], residual_[i]);
      rhs[i] = slope[i] == 0.0 ? 0.0 : residual_[i];
    });
    system_->assemble(model, a_, slope, dt, water_);
    system_->solver.setTolerance(settings_.linear_tolerance);
    // ILU(0) and its triangular solves are serial; Eigen's threaded
    // products between them only woke the team for little work.
    particles::serially([&] {
      system_->solver.compute(system_->A);
      x = system_->solver.solveWithGuess(rhs, Eigen::VectorXd::Zero(n));
    });
    stats_.linear_iterations += static_cast<std::size_t>(system_->solver.iterations());

    // The new enthalpies; a pinned particle takes what its row leaves over.
    particles::for_each_particle(n, [&](std::size_t i) {
      double dH;
      if (slope[i] != 0.0) {
        dH = x[i] / slope[i];
      } else {
        double inflow = residual_[i];
        for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
          const std::uint32_t j = P.column[e];
          double dTj = 0.0;
          if (j < n) dTj = x[j];
          else if (!W.row_start.empty())
            for (std::size_t m = W.row_start[j - n]; m < W.row_start[j - n + 1]; ++m)
              dTj -= W.weight[m] * x[W.column[m]];
          inflow += a_[e] * dTj;
          if (water_ && j < n && j != i && water_->pair_flux()[e] < 0.0)
            inflow -= water_->water_heat_capacity() * water_->pair_flux()[e] * dTj / V[i];
        }
        dH = dt * inflow;
      }
      double next = H[i] + dH;
      const double kinks[2] = {0.0, model.law_of(i).latent_enthalpy()};
      for (double k : kinks)
        if ((H[i] < k && next > k) || (H[i] > k && next < k)) next = k;  // stop on the kink
      next_H_[i] = next;
    });
    for (std::size_t i = 0; i < n; ++i) model.set_enthalpy(i, next_H_[i]);
    model.apply_boundaries(t + dt);
  }
  return false;
}

}  // namespace frostwall::thermal
