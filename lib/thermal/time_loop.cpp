#include "thermal/time_loop.hpp"

#include <algorithm>

namespace frostwall::thermal {

TimeLoopResult run_time_loop(ThermalModel& model, Integrator& integrator, double t_end,
                             const std::vector<double>& snapshots, const TimeLoopObservers& observers) {
  TimeLoopResult result;
  result.boundary_heat.assign(model.boundaries().size(), 0.0);
  std::size_t next = 0;
  double t = 0.0;
  model.apply_boundaries(0.0);
  if (observers.after_step) observers.after_step(model, t);
  while (t < t_end) {
    const double target = next < snapshots.size() ? std::min(snapshots[next], t_end) : t_end;
    double dt = integrator.preferred_step(model);
    if (observers.step_limit) dt = std::min(dt, observers.step_limit());
    // Land on the target; avoid a sliver step just before it.
    if (t + 1.5 * dt >= target) dt = (t + dt >= target) ? target - t : 0.5 * (target - t);
    const auto heat = integrator.advance(model, t, dt);
    for (std::size_t b = 0; b < heat.size(); ++b) result.boundary_heat[b] += heat[b];
    t = (t + dt >= target) ? target : t + dt;
    ++result.steps;
    model.apply_boundaries(t);
    if (observers.after_step) observers.after_step(model, t);
    while (next < snapshots.size() && snapshots[next] <= t) {
      if (observers.snapshot) observers.snapshot(model, t, next);
      ++next;
    }
    if (observers.progress) observers.progress(t, t_end);
    if (observers.finished && observers.finished()) break;
  }
  return result;
}

}  // namespace frostwall::thermal
