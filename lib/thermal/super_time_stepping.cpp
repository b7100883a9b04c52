#include "thermal/super_time_stepping.hpp"

#include <cmath>
#include <limits>

#include "particles/parallel.hpp"

namespace frostwall::thermal {

namespace {
constexpr double safety = 0.8;           // of the Gershgorin limit: k rises as particles freeze within a step
constexpr double spectral_safety = 0.9;  // of the eigenvalue's limit: the power iteration's estimate is from below

double smallest_capacity(const PhaseChangeLaw& law) {
  return 1.0 /
         std::max(law.temperature_slope(-1.0, -1.0), law.temperature_slope(2.0 * law.latent_enthalpy() + 1.0, 1.0));
}

// Largest |eigenvalue| of dT/dt = J T for the model's coefficients now and
// each particle's smallest heat capacity C_i (boundaries held at zero,
// beyond-wall particles following their free ones). J is self-adjoint in
// the inner product weighted by V_i C_i (V_i a_ij = V_j a_ji), so the power
// iteration's growth factor rises towards it from below; the caller keeps
// a margin.
double largest_eigenvalue(const ThermalModel& model) {
  const auto& P = model.pairs();
  const auto& W = model.beyond_wall();
  const auto& V = model.volume();
  const std::vector<double>& a = model.pair_coefficients();
  const std::size_t n = P.n_free, N = model.size();
  std::vector<double> x(N, 0.0), y(n, 0.0), C(n);
  for (std::size_t i = 0; i < n; ++i) C[i] = smallest_capacity(model.law_of(i));
  // A start with every wavelength in it (the stiffest is the grid scale).
  for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(1.7 * i) + std::cos(0.37 * double(i) * double(i));
  double lambda = 0.0;
  for (int it = 0; it < 150; ++it) {
    for (std::size_t i = n; i < N; ++i) x[i] = W.row_start.empty() || W.on_wall(i - n) ? 0.0 : -W.value(i - n, x);
    particles::for_each_particle(n, [&](std::size_t i) {
      double r = 0.0;
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) r += a[e] * (x[P.column[e]] - x[i]);
      y[i] = r / C[i];
    });
    const double xx = particles::sum_over_particles(n, [&](std::size_t i) { return V[i] * C[i] * x[i] * x[i]; });
    const double yy = particles::sum_over_particles(n, [&](std::size_t i) { return V[i] * C[i] * y[i] * y[i]; });
    if (!(yy > 0.0) || !(xx > 0.0)) return 0.0;
    lambda = std::sqrt(yy / xx);
    for (std::size_t i = 0; i < n; ++i) x[i] = y[i] / lambda;
  }
  return lambda;
}

double smallest_capacity(const ThermalModel& model) {
  double C = smallest_capacity(model.laws()[0]);
  for (const auto& law : model.laws()) C = std::min(C, smallest_capacity(law));
  return C;
}

}  // namespace

SuperTimeStepping::SuperTimeStepping(double step_change, double first_step)
    : control_(step_change, first_step, std::numeric_limits<double>::infinity()) {}

double SuperTimeStepping::preferred_step(const ThermalModel&) const {
  const int s = max_stages;
  return dt_fe_ > 0.0 ? std::min(control_.step(), dt_fe_ * (s * s + s - 2.0) / 4.0) : control_.step();
}

double SuperTimeStepping::forward_euler_limit(const ThermalModel& model) {
  // dH_i/dt = sum_e a_e (T_j - T_i), T = H / C: the rate's Jacobian row i has
  // |diagonal| + |off-diagonals| <= (2 sum_e a_e + extension terms) / C_min.
  // A fixed particle beyond a wall follows the free ones with its weights.
  const std::vector<double>& a = model.pair_coefficients();
  const auto& P = model.pairs();
  const auto& W = model.beyond_wall();
  const double C_min = smallest_capacity(model);
  const std::size_t n = P.n_free;
  const double worst = particles::max_over_particles(n, [&](std::size_t i) {
    double row = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
      const std::uint32_t j = P.column[e];
      double follow = j < n ? 1.0 : 0.0;
      if (j >= n && !W.row_start.empty())
        for (std::size_t m = W.row_start[j - n]; m < W.row_start[j - n + 1]; ++m) follow += std::abs(W.weight[m]);
      row += std::abs(a[e]) * (1.0 + follow);
    }
    return row;
  });
  return worst > 0.0 ? safety * 2.0 * C_min / worst : 1e300;
}

double SuperTimeStepping::spectral_limit(const ThermalModel& model) {
  double lambda = 0.0;
  for (bool frozen : {true, false}) {  // all frozen, all unfrozen
    ThermalModel state = model;
    for (std::size_t i = 0; i < state.size(); ++i)
      state.set_enthalpy(i, frozen ? -1.0 : 2.0 * state.law_of(i).latent_enthalpy() + 1.0);
    lambda = std::max(lambda, largest_eigenvalue(state));
  }
  // 150 iterations reach the eigenvalue to about 2 % from below on our
  // clouds; 0.9 covers that with room.
  return lambda > 0.0 ? spectral_safety * 2.0 / lambda : 0.0;
}

int SuperTimeStepping::stages_for(double dt, double dt_fe) {
  const double s = 0.5 * (std::sqrt(9.0 + 16.0 * dt / dt_fe) - 1.0);
  return std::max(2, static_cast<int>(std::ceil(s - 1e-12)));
}

std::vector<double> SuperTimeStepping::advance(ThermalModel& model, double t, double dt) {
  const std::size_t n = model.free_count();
  const std::size_t nb = model.boundaries().size();
  control_.remember(model);
  if (!(dt_spectral_ > 0.0)) dt_spectral_ = spectral_limit(model);
  // The spectral limit holds for every state (it is found at the stiffest);
  // the Gershgorin bound of the state now only stands in when it failed
  // (on the single ring it was 0.76 of the spectral limit at every step).
  dt_fe_ = dt_spectral_ > 0.0 ? dt_spectral_ : forward_euler_limit(model);
  const int s = stages_for(dt, dt_fe_);

  // Legendre coefficients: b_j = (j^2 + j - 2) / (2 j (j + 1)), b_0 = b_1 = b_2 = 1/3.
  auto b = [](int j) { return j < 2 ? 1.0 / 3.0 : (j * j + j - 2.0) / (2.0 * j * (j + 1.0)); };
  const double w1 = 4.0 / (s * s + s - 2.0);

  // Each stage is a combination of earlier states and rate evaluations; the
  // heat from the boundaries is carried through the same combination, so the
  // step's energy balance is exact (free-free fluxes cancel pairwise).
  Y0_ = control_.before();
  model.apply_boundaries(t);
  model.conduction_rate(L0_);
  const std::vector<double> q0 = model.boundary_heat_rate();
  std::vector<double> Q0(nb, 0.0), Qprev2(nb, 0.0), Qprev(nb), Qnext(nb);

  // Stage 1.
  const double mu1 = b(1) * w1;
  Yprev2_ = Y0_;
  Yprev_.resize(n);
  for (std::size_t k = 0; k < nb; ++k) Qprev[k] = mu1 * dt * q0[k];
  model.update_free([&](std::size_t i) { return Yprev_[i] = Y0_[i] + mu1 * dt * L0_[i]; });
  double c_prev2 = 0.0, c_prev = mu1;  // stage times, as fractions of dt

  for (int j = 2; j <= s; ++j) {
    const double mu = (2.0 * j - 1.0) / j * b(j) / b(j - 1);
    const double nu = -(j - 1.0) / j * b(j) / b(j - 2);
    const double mu_t = mu * w1;
    const double gamma_t = -(1.0 - b(j - 1)) * mu_t;
    model.apply_boundaries(t + c_prev * dt);
    model.conduction_rate(L_);
    const std::vector<double> q = model.boundary_heat_rate();
    for (std::size_t k = 0; k < nb; ++k)
      Qnext[k] = mu * Qprev[k] + nu * Qprev2[k] + (1.0 - mu - nu) * Q0[k] + mu_t * dt * q[k] + gamma_t * dt * q0[k];
    double* const Y1 = Yprev_.data();
    double* const Y2 = Yprev2_.data();
    const double *const Y0 = Y0_.data(), *const L = L_.data(), *const L0 = L0_.data();
    const double c0 = 1.0 - mu - nu, cL = mu_t * dt, cL0 = gamma_t * dt;
    model.update_free([=](std::size_t i) {
      const double Y = mu * Y1[i] + nu * Y2[i] + c0 * Y0[i] + cL * L[i] + cL0 * L0[i];
      Y2[i] = Y1[i];
      Y1[i] = Y;
      return Y;
    });
    std::swap(Qprev2, Qprev);
    std::swap(Qprev, Qnext);
    const double c = mu * c_prev + nu * c_prev2 + mu_t + gamma_t;
    c_prev2 = c_prev;
    c_prev = c;
  }
  ++stats_.steps;
  stats_.stages += static_cast<std::size_t>(s);
  control_.adapt(model, dt);
  return Qprev;
}

}  // namespace frostwall::thermal
