// RKL2 super-time-stepping (Meyer, Balsara & Aslam, J. Comput. Phys. 257,
// 2014): an explicit step of s stages whose stability polynomial is built
// from Legendre polynomials, stable up to
//     dt = dt_fe (s^2 + s - 2) / 4,
// dt_fe the forward-Euler limit. A step as long as accuracy allows then
// costs s ~ sqrt(dt / dt_fe) conduction-rate evaluations instead of
// dt / dt_fe, with no linear system and no iteration for the latent heat:
// every stage is an explicit update of the enthalpy, so the phase change
// is handled exactly as in the paper's forward Euler. Second order in time.
//
// The step is chosen by the freezing activity (step_control.hpp); the
// stage count then follows from the forward-Euler limit of the operator's
// largest eigenvalue over all states (power iteration, once), or the
// Gershgorin bound of the state now if that failed.
#pragma once

#include <vector>

#include "thermal/integrator.hpp"
#include "thermal/step_control.hpp"

namespace frostwall::thermal {

struct SuperTimeSteppingStatistics {
  std::size_t steps = 0, stages = 0;
};

class SuperTimeStepping final : public Integrator {
 public:
  // step_change: see ActivityStepControl; first_step in seconds.
  SuperTimeStepping(double step_change, double first_step);
  // No step longer than max_step from now on.
  void limit_step(double max_step) { control_.limit(max_step); }
  // The model's pairs changed (ground taken out, a lining placed): the
  // stability limit is found again at the next step.
  void forget_stability_limit() { dt_spectral_ = 0.0; }
  // The activity's step, at most max_stages stages long at the last
  // forward-Euler limit seen.
  double preferred_step(const ThermalModel&) const override;
  std::vector<double> advance(ThermalModel& model, double t, double dt) override;
  const char* name() const override { return "rkl2"; }
  const SuperTimeSteppingStatistics& statistics() const { return stats_; }

  // The forward-Euler stability limit of the model's conduction operator now
  // (Gershgorin: safe, but about 1.6x too strict on an SPH Laplacian).
  static double forward_euler_limit(const ThermalModel& model);
  // The limit from the operator's largest eigenvalue at its stiffest state
  // (every particle frozen, or every one unfrozen, at the smallest heat
  // capacity), by power iteration: valid for the whole run, since a pair's
  // coefficient lies between its frozen and unfrozen values.
  static double spectral_limit(const ThermalModel& model);
  // Stages needed for a step dt (at least 2).
  static int stages_for(double dt, double dt_fe);
  static constexpr int max_stages = 100;

 private:
  ActivityStepControl control_;
  double dt_fe_ = 0.0;        // forward-Euler limit at the last step (0: none yet)
  double dt_spectral_ = 0.0;  // spectral_limit, found at the first step
  SuperTimeSteppingStatistics stats_;
  std::vector<double> Y0_, Yprev_, Yprev2_, L0_, L_;
};

}  // namespace frostwall::thermal
