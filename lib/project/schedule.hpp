// A temperature (or any quantity) that may change in time.
#pragma once

#include <utility>
#include <vector>

namespace frostwall::project {

// A wall temperature: constant, or [time, degC] points linear in between and
// held constant outside the first and last point.
struct TemperatureSchedule {
  std::vector<std::pair<double, double>> points;  // (seconds, degC), sorted
  double at(double t_seconds) const;
  bool constant() const { return points.size() == 1; }
  static TemperatureSchedule fixed(double degC) { return {{{0.0, degC}}}; }
};

}  // namespace frostwall::project
