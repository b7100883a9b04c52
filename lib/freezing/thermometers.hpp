// The project's thermometers (`monitoring`) on a heat run: the one sensor
// model of `frostwall run`'s monitoring, of calibration's forward runs and
// of the report.
//  - In space, a sensor reads the field as the snapshot files show it in
//    ParaView: linear on the Delaunay triangle round it
//    (post::TriangleProbe), over the particles the files show and their
//    mirror images; a sensor anywhere in the section is first mapped into
//    the simulated wedge by the section's symmetry.
//  - In time, linear between the two steps around the time asked. The run
//    keeps that interpolation within `numerics.sensor_tolerance`: from the
//    sensors' last three readings, their second derivative T'' bounds the
//    next step, dt <= sqrt(8 tol / |T''|) (the largest error of linear
//    interpolation over a step being |T''| dt^2 / 8).
#pragma once

#include <vector>

#include "freezing/model.hpp"
#include "post/triangle_probe.hpp"

namespace frostwall::freezing {

class Thermometers {
 public:
  Thermometers(const project::Project& p, const Model& m);

  std::size_t size() const { return probe_.size(); }
  // Every sensor's reading of a field (one value per particle).
  std::vector<double> read(const std::vector<double>& field) const { return probe_(field); }
  // After each step of the run, and at its start (t = 0).
  void after_step(const thermal::ThermalModel& m, double t);
  // Sensor k at time tau between the last two steps (clamped to them).
  double at(std::size_t k, double tau) const;
  // The longest next step that keeps linear interpolation in time within
  // the tolerance at every sensor (infinite before three readings).
  double step_limit() const { return step_limit_; }

 private:
  post::TriangleProbe probe_;
  double tolerance_;
  // The last three readings, newest first, and their times.
  std::vector<double> now_, before_, earlier_;
  double t_now_ = 0.0, t_before_ = 0.0, t_earlier_ = 0.0;
  int seen_ = 0;
  double step_limit_;
};

// Where each of the project's sensors is read: mapped into the simulated
// wedge by the section's symmetry (the field there is the same by
// construction); as given in a plain geometry.
std::vector<particles::Vec<2>> sensor_points(const project::Project& p, const Model& m);

}  // namespace frostwall::freezing
