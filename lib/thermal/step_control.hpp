// The step of the integrators that choose their own (implicit, RKL2): the
// largest enthalpy change of a particle per step is held near a fraction
// of the latent heat, so a particle takes a few steps to freeze and the
// front moves a fraction of a spacing per step, however stiff the rest.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "particles/parallel.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::thermal {

class ActivityStepControl {
 public:
  // max_step bounds the step where nothing changes any more (an insulated
  // body at equilibrium would otherwise grow it without end).
  ActivityStepControl(double step_change, double first_step, double max_step, double growth = 1.5)
      : step_change_(step_change), growth_(growth), max_step_(max_step), step_(std::min(first_step, max_step)) {}

  double step() const { return step_; }
  // Enthalpies of the free particles before the step.
  void remember(const ThermalModel& model) {
    before_.assign(model.enthalpy().begin(), model.enthalpy().begin() + model.free_count());
  }
  const std::vector<double>& before() const { return before_; }
  // After a step of length dt: the next step from the change it made.
  void adapt(const ThermalModel& model, double dt) {
    const double scale = enthalpy_scale(model);
    const auto& H = model.enthalpy();
    double change = 0.0;
    if (model.laws().size() == model.shared_scale_laws()) {
      change = particles::max_over_particles(model.free_count(),
                                             [&](std::size_t i) { return std::abs(H[i] - before_[i]) / scale; });
    } else {  // materials added during the run (a lining) on their own scale
      std::vector<double> scales(model.laws().size(), scale);
      for (std::size_t m = model.shared_scale_laws(); m < scales.size(); ++m)
        scales[m] = enthalpy_scale(model.laws()[m]);
      change = particles::max_over_particles(
          model.free_count(), [&](std::size_t i) { return std::abs(H[i] - before_[i]) / scales[model.material(i)]; });
    }
    const double proposed = change > 0.0 ? 0.9 * dt * step_change_ / change : growth_ * step_;
    step_ = std::min(max_step_, std::clamp(proposed, 0.25 * step_, growth_ * step_));
  }
  void shorten_to(double dt) { step_ = std::min(step_, dt); }
  void limit(double max_step) {
    max_step_ = max_step;
    step_ = std::min(step_, max_step);
  }

  // The latent heat, or for a soil without one the enthalpy of 2 K.
  static double enthalpy_scale(const PhaseChangeLaw& law) {
    const double Tf = law.freezing_point();
    return std::max(law.latent_enthalpy(), law.enthalpy(Tf + 1.0) - law.enthalpy(Tf - 1.0));
  }
  // Several materials: the smallest of their scales (of the materials the
  // model was built with; one added later keeps its own, adapt()).
  static double enthalpy_scale(const ThermalModel& model) {
    double scale = enthalpy_scale(model.laws()[0]);
    for (std::size_t m = 1; m < model.shared_scale_laws(); ++m)
      scale = std::min(scale, enthalpy_scale(model.laws()[m]));
    return scale;
  }

 private:
  double step_change_, growth_, max_step_, step_;
  std::vector<double> before_;
};

}  // namespace frostwall::thermal
