// Time integrators advance a ThermalModel from t to t + dt. The explicit
// one is the SPH paper's forward Euler; the implicit one (backward_euler.hpp)
// and super time stepping (super_time_stepping.hpp) implement the same
// interface and choose their own step.
#pragma once

#include <memory>
#include <vector>

#include "project/project.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::thermal {

class Integrator {
 public:
  virtual ~Integrator() = default;
  // The step the integrator wants next (before landing on an output time).
  virtual double preferred_step(const ThermalModel& model) const = 0;
  // Advances from t to t + dt; returns the heat that entered the free
  // particles from each boundary during the step, J.
  virtual std::vector<double> advance(ThermalModel& model, double t, double dt) = 0;
  virtual const char* name() const = 0;
  // A wrapper (flowing groundwater around the conduction) returns what it
  // wraps, so step limits and statistics reach the conduction integrator.
  virtual Integrator* wrapped() const { return nullptr; }
};

// The integrator of type T in a chain of wrappers, or nullptr.
template <class T>
T* find_integrator(Integrator* integrator) {
  for (; integrator; integrator = integrator->wrapped())
    if (auto* found = dynamic_cast<T*>(integrator)) return found;
  return nullptr;
}

// Forward Euler with the paper's step dt = beta h^2 / alpha_max (its eq. 10
// prints k where the diffusivity alpha = k / (rho C) is meant).
class ExplicitEuler final : public Integrator {
 public:
  ExplicitEuler(double beta, double h) : beta_(beta), h_(h) {}
  double preferred_step(const ThermalModel& model) const override { return beta_ * h_ * h_ / model.max_diffusivity(); }
  std::vector<double> advance(ThermalModel& model, double t, double dt) override;
  const char* name() const override { return "explicit"; }

 private:
  double beta_, h_;
  std::vector<double> rate_;
};

}  // namespace frostwall::thermal
