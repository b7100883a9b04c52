#include "thermal/time_loop.hpp"

#include <algorithm>

namespace frostwall::thermal {

TimeLoop::TimeLoop(ThermalModel& model, Integrator& integrator, double t_end, std::vector<double> snapshots,
                   TimeLoopObservers observers)
    : model_(model),
      integrator_(integrator),
      t_end_(t_end),
      snapshots_(std::move(snapshots)),
      observers_(std::move(observers)) {
  result_.boundary_heat.assign(model.boundaries().size(), 0.0);
  model.apply_boundaries(0.0);
  if (observers_.after_step) observers_.after_step(model, t_);
  done_ = t_ >= t_end_;
}

double TimeLoop::advance_to(double stop) {
  stop = std::min(stop, t_end_);
  while (!done_ && t_ < stop) {
    const double target = std::min(next_ < snapshots_.size() ? snapshots_[next_] : t_end_, stop);
    double dt = integrator_.preferred_step(model_);
    if (observers_.step_limit) dt = std::min(dt, observers_.step_limit());
    // Land on the target; avoid a sliver step just before it.
    if (t_ + 1.5 * dt >= target) dt = (t_ + dt >= target) ? target - t_ : 0.5 * (target - t_);
    const auto heat = integrator_.advance(model_, t_, dt);
    for (std::size_t b = 0; b < heat.size(); ++b) result_.boundary_heat[b] += heat[b];
    t_ = (t_ + dt >= target) ? target : t_ + dt;
    ++result_.steps;
    model_.apply_boundaries(t_);
    if (observers_.after_step) observers_.after_step(model_, t_);
    while (next_ < snapshots_.size() && snapshots_[next_] <= t_) {
      if (observers_.snapshot) observers_.snapshot(model_, t_, next_);
      ++next_;
    }
    if (observers_.progress) observers_.progress(t_, t_end_);
    if (t_ >= t_end_ || (observers_.finished && observers_.finished())) done_ = true;
  }
  return t_;
}

TimeLoopResult run_time_loop(ThermalModel& model, Integrator& integrator, double t_end,
                             const std::vector<double>& snapshots, const TimeLoopObservers& observers) {
  TimeLoop loop(model, integrator, t_end, snapshots, observers);
  loop.advance_to(t_end);
  return loop.result();
}

}  // namespace frostwall::thermal
