// Marches a model to the end time, landing exactly on every output time,
// and tells observers after each step and at each snapshot. A TimeLoop can
// also be advanced in parts, to any stop in between (landing on it as on a
// snapshot), so that several models can march side by side and exchange
// what couples them at the stops.
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

class TimeLoop {
 public:
  // Starts at t = 0: the boundaries applied and after_step called there.
  // Snapshots ascending, in (0, t_end].
  TimeLoop(ThermalModel& model, Integrator& integrator, double t_end, std::vector<double> snapshots,
           TimeLoopObservers observers);
  // Steps until the time reaches `stop` (or t_end, or finished() says so);
  // returns the time reached.
  double advance_to(double stop);
  bool done() const { return done_; }
  const TimeLoopResult& result() const { return result_; }

 private:
  ThermalModel& model_;
  Integrator& integrator_;
  double t_end_;
  std::vector<double> snapshots_;
  TimeLoopObservers observers_;
  TimeLoopResult result_;
  std::size_t next_ = 0;
  double t_ = 0.0;
  bool done_ = false;
};

// Runs from t = 0 to t_end. Snapshots (ascending, in (0, t_end]) are hit
// exactly by shortening the step before them.
TimeLoopResult run_time_loop(ThermalModel& model, Integrator& integrator, double t_end,
                             const std::vector<double>& snapshots, const TimeLoopObservers& observers);

}  // namespace frostwall::thermal
