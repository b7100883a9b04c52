// The coupled run's guard against an unstable step. After every chunk of
// DEM steps the grains' kinetic energy and fastest speed are compared with
// what the physics can give them: a fall through the whole box plus the
// water's fastest interstitial speed, v_max = sqrt(2 |g| H) + max |U| / eps.
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
  StabilityWatch(const project::CfdDem& c, double dt, int interval);
  // Collective. Throws UnstableRun naming the time, the energy, the
  // fastest grain, the bound and the likely cause; else keeps the peak,
  // and the motion at t when `sample` (the run's 201 sample times).
  void check(double t, const CfdDemCoupling& coupling, bool sample);
  // summary.json's `stability`: the drag's coupling, the hold against the
  // shortest relaxation time, the peak energy and speed, and the series.
  nlohmann::json summary(const CfdDemCoupling& coupling) const;
  // The speed bound (m/s) with the water's fastest interstitial speed u_water.
  double speed_bound(double u_water) const;
  int interval() const { return interval_; }

 private:
  const project::CfdDem& c_;
  double dt_;
  int interval_;
  double fall_speed_;  // sqrt(2 |g| H)
  struct Row {
    double t, energy, fastest, bound;
  };
  Row peak_energy_{}, peak_speed_{};
  std::vector<Row> series_;
};

// The water's fastest interstitial speed on the grid (m/s).
double fastest_water(const pore_water::FluidGrid& grid);

}  // namespace frostwall::cfd_dem
