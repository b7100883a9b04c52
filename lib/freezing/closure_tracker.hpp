// Closure and front contact of a shaft run, followed step by step: the
// detector (post/closure.hpp) fed with H / H_latent, and the integrator's
// step held short while the gap between the columns freezes, so that the
// closure is resolved by steps rather than bridged by one.
#pragma once

#include <optional>
#include <vector>

#include "post/closure.hpp"
#include "post/gap_closure.hpp"
#include "freezing/model.hpp"

namespace frostwall::freezing {

class ClosureTracker {
 public:
  // While the gap freezes, a step may lower the bottleneck by at most this
  // share of the latent heat. With RKL2's steps of up to a day late in a
  // run, the last neck particle otherwise froze within one long step and
  // the single ring closed 2.2 % late (0.30 d; 0.07 d on the four-hole);
  // at 0.05 it is +0.2 % for 16 more steps (bench/README.md).
  static constexpr double step_fall = 0.05;

  // longest_step: the run's step limit outside the freezing gap (s).
  ClosureTracker(const Model& m, double t_end, double longest_step);
  // Under seepage: while a gap's bridge freezes, a step may lower its
  // largest latent share by at most this much (the gap's own closure day
  // is then resolved by steps, as the wall's is by step_fall).
  static constexpr double gap_fall = 0.25;

  // After each step (and at t = 0); gaps: closure per gap, observed up to t
  // (under seepage; else null).
  void after_step(const thermal::ThermalModel& model, double t, const post::GapClosure* gaps = nullptr);
  std::optional<double> closure_time() const { return watch_.closure_time(); }  // s
  std::optional<double> contact_time() const { return watch_.contact_time(); }  // s

 private:
  Model const& model_;
  post::ClosureDetector detector_;
  post::ClosureWatch watch_;
  double check_interval_, longest_step_;
  std::vector<double> latent_left_;
};

}  // namespace frostwall::freezing
