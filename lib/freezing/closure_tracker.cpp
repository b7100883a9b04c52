#include "freezing/closure_tracker.hpp"

#include <algorithm>

#include "thermal/backward_euler.hpp"
#include "thermal/super_time_stepping.hpp"

namespace frostwall::freezing {

ClosureTracker::ClosureTracker(const Model& m, double t_end, double longest_step)
    : model_(m),
      detector_(m.particles(), m.shaft->far_field_radius),
      watch_(detector_),
      check_interval_(t_end / 2000.0),
      longest_step_(longest_step) {}

void ClosureTracker::after_step(const thermal::ThermalModel& model, double t, const post::GapClosure* gaps) {
  if (watch_.due(t)) {
    model.latent_left(latent_left_);
    watch_.observe(t, latent_left_, check_interval_);
    // RKL2 and the implicit steps are long enough to matter (explicit ones are short).
    if (auto* rkl2 = thermal::find_integrator<thermal::SuperTimeStepping>(model_.integrator.get())) {
      const auto resolve = watch_.time_to_fall(step_fall);
      rkl2->limit_step(resolve ? std::min(*resolve, longest_step_) : longest_step_);
    }
  }
  if (auto* implicit = thermal::find_integrator<thermal::BackwardEuler>(model_.integrator.get())) {
    double limit = longest_step_;
    if (const auto resolve = watch_.time_to_fall(step_fall)) limit = std::min(limit, *resolve);
    if (gaps)
      if (const auto resolve = gaps->time_to_fall(gap_fall)) limit = std::min(limit, *resolve);
    implicit->limit_step(limit);
  }
}

}  // namespace frostwall::freezing
