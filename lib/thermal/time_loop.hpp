// Marches a model to the end time, landing exactly on every output time,
// and tells observers after each step and at each snapshot.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "thermal/integrator.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::thermal {

struct TimeLoopObservers {
  std::function<void(const ThermalModel&, double t)> after_step;               // optional
  std::function<void(const ThermalModel&, double t, std::size_t k)> snapshot;  // optional
  std::function<void(double t, double t_end)> progress;                        // optional
  std::function<double()> step_limit;                                          // optional: the longest next step
  std::function<bool()> finished;  // optional: ends the run early when it returns true
};

struct TimeLoopResult {
  std::size_t steps = 0;
  std::vector<double> boundary_heat;  // J that entered from each boundary
};

// Runs from t = 0 to t_end. Snapshots (ascending, in (0, t_end]) are hit
// exactly by shortening the step before them.
TimeLoopResult run_time_loop(ThermalModel& model, Integrator& integrator, double t_end,
                             const std::vector<double>& snapshots, const TimeLoopObservers& observers);

}  // namespace frostwall::thermal
