// The coupled run's guard against an unstable step. After every chunk of
// DEM steps the grains' kinetic energy and fastest speed are compared with
// what the physics can give them: a fall through the whole box plus the
// water's fastest interstitial speed, v_max = sqrt(2 |g| H) + u_w. u_w is
// fixed before the grains can drive the water (which an instability would
// speed up with them): the inflow's Darcy velocity over the grid's least
// porosity, or with a pressure inflow the water's fastest interstitial
// speed at the first check.
// A grain faster than three times v_max, or a kinetic energy above every
// grain moving at v_max, is an instability (a DEM step too long for the
// contacts, or a drag held longer than its relaxation time), and the run
// stops with that diagnosis before LAMMPS starts losing grains.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "cfd_dem/coupling.hpp"
#include "project/cfd_dem.hpp"

namespace frostwall::cfd_dem {

// Thrown on every rank alike (the measures are reduced over all ranks).
class UnstableRun : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StabilityWatch {
 public:
  // `interval`: coupling.interval as given, else the chosen cap.
  StabilityWatch(const project::CfdDem& c, double dt, int interval);
  // DEM steps until the next fluid update: coupling.interval as given;
  // chosen, at most the cap and a fifth of the shortest relaxation time the
  // held forces answer to (the bed's, and a grain's own drag when it is
  // held explicitly).
  int next_interval(const CfdDemCoupling& coupling);
  // Collective. Throws UnstableRun naming the time, the energy, the
  // fastest grain, the bound and the likely cause; else keeps the peak,
  // and the motion at t when `sample` (the run's 201 sample times).
  void check(double t, const CfdDemCoupling& coupling, bool sample);
  // summary.json's `stability`: the drag's coupling, the hold against the
  // shortest relaxation time, the peak energy and speed, and the series.
  nlohmann::json summary(const CfdDemCoupling& coupling) const;
  // The speed bound (m/s), once u_w is known (after the first check).
  double speed_bound() const { return fall_speed_ + water_; }

 private:
  const project::CfdDem& c_;
  double dt_;
  int interval_;
  bool given_;
  int shortest_ = 0, updates_ = 0, last_ = 0;
  double held_over_drag_ = 0.0, held_over_bed_ = 0.0;  // the largest met
  double fall_speed_;                                  // sqrt(2 |g| H)
  double water_ = -1.0;                                // u_w (m/s); negative until the first check
  struct Row {
    double t, energy, fastest, bound;
  };
  Row peak_energy_{}, peak_speed_{};
  std::vector<Row> series_;
};

}  // namespace frostwall::cfd_dem
