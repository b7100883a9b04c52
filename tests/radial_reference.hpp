// An independent reference for the SPH solver: one freeze pipe alone in a
// large domain, solved as a 1-D radial (axisymmetric) finite-volume problem
// in enthalpy form (physics.md section 1),
//     dH/dt = (1/r) d/dr (r k dT/dr),   a < r < R,
// with the pipe wall r = a held at T_pipe(t), the outer boundary r = R held
// at T_far (or adiabatic), ground initially at T_init.
//
// The phase-change law is frostwall's own (thermal::PhaseChangeLaw: H(T),
// T(H), f(H), k(f) = conductivity(f, 0)), so that a comparison with SPH is a
// comparison of spatial discretisations only. Everything else is
// independent of SPH:
//   - uniform grid of N cells between a and R (dr = (R - a)/N, the requested
//     spacing rounded to fit), cell centres r_i = a + (i + 1/2) dr, cell
//     volumes V_i = r_i dr (exactly (r_{i+1/2}^2 - r_{i-1/2}^2)/2; the
//     factor 2 pi and the unit length along the pipe are omitted throughout,
//     so energies and heats are per metre of pipe and per radian);
//   - face flux r_f k_f (T_{i+1} - T_i)/dr with k_f the harmonic mean of the
//     two cells' conductivities; at a Dirichlet boundary the half-cell
//     distance dr/2 and the cell's own conductivity;
//   - backward Euler in time, the nonlinear step solved by the
//     Voller-Swaminathan source update: linearise H about the current
//     iterate (H = H^k + dH/dT (T - T^k), a cell inside an isothermal
//     freezing plateau pinned at the freezing point), solve the tridiagonal
//     system for T, then take H of every cell from its own discrete balance
//     with those temperatures. Conductivities are lagged one iterate. The
//     iteration stops when every cell's new H lies on the branch of the law
//     it was linearised on (so T(H) is what the linear solve assumed) and f
//     has settled; a step that does not converge is halved and retried.
//     Because H is updated from the fluxes, sum V_i H_i changes by exactly
//     the boundary heat (to round-off) whatever the iteration error.
//   - step size dt = clamp(growth * t, dt_min, dt_max), so the front moves
//     a fixed small share of itself per step (it grows like sqrt(t)); the
//     default growth = dr / (1 m) makes time and space errors fall together
//     (both first order; for the sand case at dr = 4 mm the time error of
//     the frozen radius is about 1e-4 relative).
// Conductivity is taken along axis 0 (an anisotropic soil has no meaning in
// this 1-D radial model). Cost: the 30-day sand case at dr = 2 mm (1468
// cells, about 4500 steps, 2.4 iterations each) takes about 0.4 s.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <vector>

#include "project/project.hpp"
#include "thermal/phase_change.hpp"

namespace frostwall::test {

struct RadialProblem {
  project::Soil soil;
  double pipe_radius = 0.0;   // a, m
  double outer_radius = 0.0;  // R, m
  double T_init = 0.0;        // degC
  double T_pipe = 0.0;        // degC, wall temperature (unless T_pipe_at is set)
  double T_far = 0.0;         // degC at r = R (unless adiabatic_far)
  bool adiabatic_far = false;
  std::function<double(double)> T_pipe_at{};  // optional: wall temperature at time t (s)
};

struct RadialOptions {
  double growth = 0.0;                                      // dt = growth * t; 0 = dr / (1 m)
  double dt_min = 0.0;                                      // s; 0 = 0.5 dr^2 / alpha_max (first steps)
  double dt_max = std::numeric_limits<double>::infinity();  // s
  double tolerance_T = 1e-9;                                // K, iteration: |T(H) - T on the linearised branch|
  double tolerance_f = 1e-6;  // iteration: change of liquid fraction (the k lag then leaves ~1e-9)
  int max_iterations = 60;    // per attempt; then the step is halved
};

class RadialReference {
 public:
  RadialReference(const RadialProblem& problem, double dr, RadialOptions options = {})
      : p_(problem), law_(problem.soil), opt_(options) {
    if (!(p_.pipe_radius > 0.0) || !(p_.outer_radius > p_.pipe_radius) || !(dr > 0.0))
      throw std::invalid_argument("RadialReference: need 0 < a < R and dr > 0");
    const auto n = static_cast<std::size_t>(std::max(2.0, std::round((p_.outer_radius - p_.pipe_radius) / dr)));
    dr_ = (p_.outer_radius - p_.pipe_radius) / static_cast<double>(n);
    if (opt_.growth <= 0.0) opt_.growth = dr_ / 1.0;  // dr in metres: first order with dr
    if (opt_.dt_min <= 0.0) opt_.dt_min = 0.5 * dr_ * dr_ / law_.max_diffusivity();
    r_.resize(n);
    V_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      r_[i] = p_.pipe_radius + (static_cast<double>(i) + 0.5) * dr_;
      V_[i] = r_[i] * dr_;
      inv_V_.push_back(1.0 / V_[i]);
    }
    H_.assign(n, law_.enthalpy(p_.T_init));
    T_.assign(n, 0.0);
    f_.assign(n, 0.0);
    refresh(H_, T_, f_);
    // The branches of the law, read off the law itself (each is linear).
    // A smooth curve's freezing branch is curved: it is linearised at each
    // iterate with the law's local slope (Newton), the others as before.
    smooth_ = law_.tabulated();
    isothermal_ = !smooth_ && p_.soil.freezing_range <= 0.0;
    const double Tf = law_.freezing_point(), Ts = Tf - p_.soil.freezing_range;
    H_l_ = smooth_ ? law_.latent_enthalpy() : law_.enthalpy(Tf);  // unfrozen end of freezing
    rho_cs_ = smooth_ ? 1.0 / law_.temperature_slope(-1.0, -1.0) : -law_.enthalpy(Ts - 1.0);  // H = 0 at Ts
    rho_cl_ = law_.enthalpy(Tf + 1.0) - H_l_;
    rho_cm_ = isothermal_ || smooth_ ? 0.0 : H_l_ / p_.soil.freezing_range;  // inside the range
    inv_rho_cs_ = 1.0 / rho_cs_;
    inv_rho_cl_ = 1.0 / rho_cl_;
    inv_rho_cm_ = isothermal_ ? 0.0 : 1.0 / rho_cm_;
    // Geometric factors of the transmissibilities: r/distance at the wall,
    // at each interior face and at the outer boundary.
    G_.resize(n + 1);
    G_[0] = p_.pipe_radius / (0.5 * dr_);
    for (std::size_t i = 1; i < n; ++i) G_[i] = (p_.pipe_radius + static_cast<double>(i) * dr_) / dr_;
    G_[n] = p_.adiabatic_far ? 0.0 : p_.outer_radius / (0.5 * dr_);
    A_.resize(n + 1);
    lo_.resize(n);
    di_.resize(n);
    up_.resize(n);
    rhs_.resize(n);
    cp_.resize(n);
    Tsol_.resize(n);
    Hk_.resize(n);
    Tk_.resize(n);
    fk_.resize(n);
    H_prev_ = H_;
  }

  // Marches (backward Euler) until time() == t_seconds exactly.
  void advance_to(double t_seconds) {
    while (t_ < t_seconds) {
      double dt = std::clamp(opt_.growth * t_, opt_.dt_min, opt_.dt_max);
      // Land exactly on the target without a sliver step just before it.
      const double remaining = t_seconds - t_;
      if (remaining <= dt) dt = remaining;
      else if (remaining < 2.0 * dt) dt = 0.5 * remaining;
      while (!step(dt)) {
        dt *= 0.5;
        if (dt < 1e-6 * opt_.dt_min) throw std::runtime_error("RadialReference: step does not converge");
      }
    }
  }

  // Where the liquid fraction first crosses 0.5 going out from the pipe:
  // linear interpolation between cell centres, the pipe wall (r = a) taken
  // as a frozen point (f = 0). r from the pipe axis; R if every cell is
  // frozen. (Before any cell freezes this gives a + dr/4, the crossing
  // between the wall and an unfrozen first cell.)
  double frozen_radius() const {
    double r_prev = p_.pipe_radius, f_prev = 0.0;
    for (std::size_t i = 0; i < r_.size(); ++i) {
      if (f_[i] >= 0.5) return r_prev + (0.5 - f_prev) / (f_[i] - f_prev) * (r_[i] - r_prev);
      r_prev = r_[i];
      f_prev = f_[i];
    }
    return p_.outer_radius;
  }

  // The radius of a circle around the pipe holding the frozen volume:
  // r^2 = a^2 + 2 sum_i (1 - f_i) V_i. With an isothermal law (one cell
  // freezing at a time) this is the enthalpy method's front, placed inside
  // the freezing cell by its frozen share: smoother in time and in dr than
  // the f = 0.5 crossing, whose interpolation between a plateau cell and
  // its neighbours wobbles by up to about 0.08 dr as the front crosses a
  // cell. The two agree within that wobble.
  double frozen_radius_by_volume() const {
    double v = 0.0;
    for (std::size_t i = 0; i < r_.size(); ++i) v += (1.0 - f_[i]) * V_[i];
    return std::sqrt(p_.pipe_radius * p_.pipe_radius + 2.0 * v);
  }

  // Linear between cell centres; the wall and (if fixed) the far boundary
  // temperatures at r = a and r = R; constant beyond the last centre when
  // the far field is adiabatic.
  double temperature_at(double r) const {
    if (r <= p_.pipe_radius) return wall_temperature(t_);
    if (r <= r_.front()) return lerp(p_.pipe_radius, wall_temperature(t_), r_.front(), T_.front(), r);
    if (r >= r_.back()) {
      if (p_.adiabatic_far) return T_.back();
      return lerp(r_.back(), T_.back(), p_.outer_radius, p_.T_far, std::min(r, p_.outer_radius));
    }
    const auto i = std::min(static_cast<std::size_t>((r - r_.front()) / dr_), r_.size() - 2);
    return lerp(r_[i], T_[i], r_[i + 1], T_[i + 1], r);
  }

  double time() const { return t_; }
  double dr() const { return dr_; }
  std::size_t cells() const { return r_.size(); }
  double cell_radius(std::size_t i) const { return r_[i]; }
  double cell_volume(std::size_t i) const { return V_[i]; }  // r_i dr, per radian and metre
  double enthalpy(std::size_t i) const { return H_[i]; }
  double temperature(std::size_t i) const { return T_[i]; }
  double liquid_fraction(std::size_t i) const { return f_[i]; }
  // sum V_i H_i, J per metre of pipe per radian.
  double energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < H_.size(); ++i) e += V_[i] * H_[i];
    return e;
  }
  // Heat that entered through the pipe wall since t = 0 (negative when the
  // pipe draws heat out), and through the outer boundary; J per metre per radian.
  double wall_heat() const { return wall_heat_; }
  double far_heat() const { return far_heat_; }
  // How well the state solves the discrete equations of the last step:
  // the largest |V_i (H_i - H_i^prev)/dt - net inflow_i| with every
  // temperature and conductivity re-evaluated from the final H, relative to
  // the largest |net inflow_i|. Small (~1e-9) when the iteration converged.
  double last_step_residual() const {
    if (steps_ == 0) return 0.0;
    const std::size_t n = r_.size();
    const double t1 = t_, dt = dt_prev_;
    std::vector<double> k(n);
    for (std::size_t i = 0; i < n; ++i) k[i] = law_.conductivity(f_[i], 0);
    auto face = [&](std::size_t i) {  // inflow into cell i through its inner face
      if (i == 0) return G_[0] * k[0] * (wall_temperature(t1) - T_[0]);
      return G_[i] * 2.0 * k[i] * k[i - 1] / (k[i] + k[i - 1]) * (T_[i - 1] - T_[i]);
    };
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double out = i + 1 == n ? G_[n] * k[n - 1] * (T_[n - 1] - (p_.adiabatic_far ? 0.0 : p_.T_far))
                                    : face(i + 1);
      const double net = face(i) - out;
      worst = std::max(worst, std::abs(V_[i] * (H_[i] - H_prev_[i]) / dt - net));
      scale = std::max(scale, std::abs(net));
    }
    return scale > 0.0 ? worst / scale : worst;
  }
  std::size_t steps() const { return steps_; }
  std::size_t iterations() const { return iterations_; }
  const thermal::PhaseChangeLaw& law() const { return law_; }

 private:
  static double lerp(double x0, double y0, double x1, double y1, double x) {
    return y0 + (y1 - y0) * (x - x0) / (x1 - x0);
  }
  double wall_temperature(double t) const { return p_.T_pipe_at ? p_.T_pipe_at(t) : p_.T_pipe; }

  void refresh(const std::vector<double>& H, std::vector<double>& T, std::vector<double>& f) const {
    for (std::size_t i = 0; i < H.size(); ++i) {
      T[i] = law_.temperature(H[i]);
      f[i] = law_.liquid_fraction(H[i]);
    }
  }

  // One backward-Euler step of length dt from (t_, H_). False (state
  // untouched) if the iteration does not converge.
  bool step(double dt) {
    const std::size_t n = r_.size();
    const double t1 = t_ + dt;
    const double Tw = wall_temperature(t1);
    const double Tfar = p_.adiabatic_far ? 0.0 : p_.T_far;
    const double Tf = law_.freezing_point(), inv_dt = 1.0 / dt;
    // First iterate: H extrapolated linearly in time from the last two
    // steps (a good guess saves an iteration of the lagged conductivities;
    // the converged step does not depend on it).
    const double w = dt_prev_ > 0.0 ? dt / dt_prev_ : 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double H = H_[i] + w * (H_[i] - H_prev_[i]);
      Hk_[i] = H;
      Tk_[i] = law_.temperature(H);
      fk_[i] = law_.liquid_fraction(H);
    }
    double q_wall = 0.0, q_far = 0.0;
    for (int it = 0; it < opt_.max_iterations; ++it) {
      ++iterations_;
      // Transmissibilities with conductivities of the current iterate:
      // A_[0] the wall, A_[i] the face between cells i-1 and i (harmonic
      // mean), A_[n] the outer boundary (0 when adiabatic).
      double k_prev = law_.conductivity(fk_[0], 0);
      A_[0] = G_[0] * k_prev;
      for (std::size_t i = 1; i < n; ++i) {
        const double k = law_.conductivity(fk_[i], 0);
        A_[i] = G_[i] * 2.0 * k * k_prev / (k + k_prev);
        k_prev = k;
      }
      A_[n] = G_[n] * k_prev;
      // Row i: (V_i/dt) (H_i^k + C_i (T_i - T_i^k) - H_i^n)
      //          = A_i (T_{i-1} - T_i) + A_{i+1} (T_{i+1} - T_i),
      // a cell inside an isothermal plateau pinned at T = Tf instead.
      for (std::size_t i = 0; i < n; ++i) {
        const double Hi = Hk_[i];
        if (isothermal_ && Hi >= 0.0 && Hi <= H_l_) {
          lo_[i] = 0.0, di_[i] = 1.0, up_[i] = 0.0, rhs_[i] = Tf;
          continue;
        }
        const double C = capacity(Hi), m = V_[i] * inv_dt;
        lo_[i] = -A_[i];
        up_[i] = -A_[i + 1];
        di_[i] = m * C + A_[i] + A_[i + 1];
        rhs_[i] = m * (C * Tk_[i] - Hi + H_[i]);
      }
      rhs_[0] -= lo_[0] * Tw;  // boundary values (their rows' A_0, A_n terms)
      rhs_[n - 1] -= up_[n - 1] * Tfar;
      lo_[0] = 0.0;
      up_[n - 1] = 0.0;
      solve_tridiagonal(n);
      // Enthalpy of every cell from its own balance with the solved T;
      // converged when each new H still lies on the branch of the law it
      // was linearised on (then the linear solve was exact for that cell)
      // and the liquid fractions, hence the lagged conductivities, have
      // settled. The branch test compares T(H) with the linearisation at
      // the same H, not with the solved T: with long steps the H taken from
      // the fluxes carries round-off amplified by dt/V, which is harmless.
      q_wall = A_[0] * (Tw - Tsol_[0]);
      q_far = A_[n] * (Tfar - Tsol_[n - 1]);
      double inflow = q_wall, off_branch = 0.0, df = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        const double outflow = i + 1 == n ? -q_far : A_[i + 1] * (Tsol_[i] - Tsol_[i + 1]);
        const double H0 = Hk_[i], T0 = Tk_[i];
        const double H = H_[i] + dt * (inflow - outflow) * inv_V_[i];
        inflow = outflow;
        const double T = law_.temperature(H), f = law_.liquid_fraction(H);
        off_branch = std::max(off_branch, std::abs(T - branch_temperature(H0, T0, H)));
        df = std::max(df, std::abs(f - fk_[i]));
        Hk_[i] = H;
        Tk_[i] = T;
        fk_[i] = f;
      }
      if (off_branch <= opt_.tolerance_T && df <= opt_.tolerance_f) {
        std::swap(H_prev_, H_);
        std::swap(H_, Hk_);
        std::swap(T_, Tk_);
        std::swap(f_, fk_);
        wall_heat_ += dt * q_wall;
        far_heat_ += dt * q_far;
        t_ = t1;
        dt_prev_ = dt;
        ++steps_;
        return true;
      }
    }
    return false;
  }

  // Solves the tridiagonal system (lo_, di_, up_, rhs_) into Tsol_:
  // Thomas elimination from both ends at once towards a middle row (two
  // independent recurrences, so twice the instruction-level parallelism of
  // the one-way sweep), then substitution outwards from the middle.
  void solve_tridiagonal(std::size_t n) {
    const std::size_t m = (n - 1) / 2, top = m, bottom = n - 1 - m;  // bottom = top or top + 1
    double c = 0.0, g = 0.0, e = 0.0, h = 0.0;
    auto down = [&](std::size_t i) {  // rows above m: T_i + c_i T_{i+1} = g_i
      const double inv = 1.0 / (di_[i] - lo_[i] * c);
      c = up_[i] * inv;
      g = (rhs_[i] - lo_[i] * g) * inv;
      cp_[i] = c;
      Tsol_[i] = g;
    };
    auto upward = [&](std::size_t j) {  // rows below m: T_j + e_j T_{j-1} = h_j
      const double inv = 1.0 / (di_[j] - up_[j] * e);
      e = lo_[j] * inv;
      h = (rhs_[j] - up_[j] * h) * inv;
      cp_[j] = e;
      Tsol_[j] = h;
    };
    for (std::size_t k = 0; k < top; ++k) {
      down(k);
      upward(n - 1 - k);
    }
    if (bottom > top) upward(m + 1);
    Tsol_[m] = (rhs_[m] - lo_[m] * g - up_[m] * h) / (di_[m] - lo_[m] * c - up_[m] * e);
    for (std::size_t k = 1; k <= bottom; ++k) {
      if (k <= top) Tsol_[m - k] -= cp_[m - k] * Tsol_[m - k + 1];
      Tsol_[m + k] -= cp_[m + k] * Tsol_[m + k - 1];
    }
  }

  // T of enthalpy H on the branch of the law through (H0, T0), extended
  // linearly beyond that branch's ends (a pinned plateau: T = Tf).
  double branch_temperature(double H0, double T0, double H) const {
    if (isothermal_ && H0 >= 0.0 && H0 <= H_l_) return law_.freezing_point();
    return T0 + (H - H0) * inverse_capacity(H0);
  }

  // dH/dT of the branch of the law H lies on (outside an isothermal
  // plateau), and its inverse.
  double capacity(double H) const {
    return H < 0.0 ? rho_cs_ : H > H_l_ ? rho_cl_ : smooth_ ? 1.0 / law_.temperature_slope(H, 1.0) : rho_cm_;
  }
  double inverse_capacity(double H) const {
    return H < 0.0 ? inv_rho_cs_ : H > H_l_ ? inv_rho_cl_ : smooth_ ? law_.temperature_slope(H, 1.0) : inv_rho_cm_;
  }

  RadialProblem p_;
  thermal::PhaseChangeLaw law_;
  RadialOptions opt_;
  double dr_ = 0.0, t_ = 0.0;
  bool isothermal_ = true, smooth_ = false;
  double H_l_ = 0.0, rho_cs_ = 0.0, rho_cl_ = 0.0, rho_cm_ = 0.0;
  double inv_rho_cs_ = 0.0, inv_rho_cl_ = 0.0, inv_rho_cm_ = 0.0;
  std::vector<double> r_, V_, inv_V_, G_, H_, T_, f_;
  std::vector<double> A_, lo_, di_, up_, rhs_, cp_, Tsol_, Hk_, Tk_, fk_, H_prev_;  // work arrays of a step
  double dt_prev_ = 0.0;
  double wall_heat_ = 0.0, far_heat_ = 0.0;
  std::size_t steps_ = 0, iterations_ = 0;
};

}  // namespace frostwall::test
