// Backward Euler on the enthalpy form, the default integrator:
//     V_i (H_i - H_i^n) / dt = V_i sum_j a_ij (T_j - T_i)     at t + dt,
// T = T(H) from the phase-change law, a_ij = G_ij k_ij with k from the
// same iterate. The step is solved by Newton's method on H, written in
// temperature increments so that the linear systems stay well scaled:
//  - a particle whose T moves with H (frozen, unfrozen, or inside a
//    freezing range) has dH = C dT, C = dH/dT;
//  - a particle inside an isothermal change has T pinned at Tf (dT = 0);
//    its enthalpy increment follows from its row after the solve.
// The law is piecewise linear, so Newton is exact once every particle is
// on the right piece; an update that would cross a kink (H = 0 or H = H_l)
// stops on it, and the next iteration continues on the new piece. This
// keeps a particle from bouncing between phases.
//
// The step adapts to the freezing activity: the largest enthalpy change
// of a particle per step is held near `step_change` of the latent heat
// (a particle takes a few steps to freeze, the front moves a fraction of a
// spacing per step).
//
// Flowing groundwater (HeatAdvection's coupled scheme) joins the same
// step: its rate, with limited faces at the iterate, is part of the
// residual, and its upwind part of the Newton matrix (which is then not
// symmetric; BiCGSTAB solves it). One system for both keeps their steady
// balance independent of the step, which splitting does not.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "thermal/integrator.hpp"
#include "thermal/step_control.hpp"

namespace frostwall::thermal {

struct BackwardEulerSettings {
  double step_change = 0.25;        // target max |dH| per step / latent heat
  double first_step = 0.0;          // s; 0: a few explicit steps' worth
  double growth = 1.5;              // largest step increase per step
  double max_steps_explicit = 1e4;  // longest step, in explicit steps
  double newton_tolerance = 1e-7;   // max |residual| dt / latent heat
  // Relative residual each Newton system is solved to. Inexact Newton
  // (1e-2) stops on the step's own residual all the same, but leaves it
  // just under the tolerance where exact solves leave it far below: the
  // insulated box then drifts 2e-8 of its heat instead of under 1e-9.
  double linear_tolerance = 1e-8;
  int max_newton = 40;
  // With water: after this many Newton iterations of a step (0: never) the
  // step's hook runs (the flow solved again for the iterate's ice) and the
  // limiter is held at the iterate (HeatAdvection::hold_limiter).
  int settle_after = 2;
};

// Counters a benchmark or a test reads after a run.
struct ImplicitStatistics {
  std::size_t steps = 0, newton_iterations = 0, linear_iterations = 0, halvings = 0;
};

class HeatAdvection;

class BackwardEuler final : public Integrator {
 public:
  BackwardEuler(BackwardEulerSettings settings, double explicit_step);
  ~BackwardEuler() override;
  double preferred_step(const ThermalModel&) const override { return control_.step(); }
  std::vector<double> advance(ThermalModel& model, double t, double dt) override;
  const char* name() const override { return "implicit"; }
  // Caps the step (a closure about to happen); infinity lifts the cap.
  void limit_step(double max_step) { control_.limit(std::min(max_step, max_step_)); }
  const ImplicitStatistics& statistics() const { return stats_; }
  // The water's heat stepped with the conduction (nullptr: conduction alone).
  void couple(HeatAdvection* water) { water_ = water; }
  // Runs once a step after settle_after Newton iterations, before the limiter is held.
  void on_settled(std::function<void(const ThermalModel&)> hook) { settled_ = std::move(hook); }

 private:
  bool try_step(ThermalModel& model, double t, double dt);

  BackwardEulerSettings settings_;
  ActivityStepControl control_;
  double max_step_;  // the settings' longest step, s
  ImplicitStatistics stats_;
  struct LinearSystem;  // the Newton matrix's fixed pattern and its solver
  std::unique_ptr<LinearSystem> system_;
  std::vector<double> residual_, next_H_;
  HeatAdvection* water_ = nullptr;
  std::function<void(const ThermalModel&)> settled_;
  std::vector<double> water_rate_, water_heat_;  // at the iterate: W per metre
};

}  // namespace frostwall::thermal
