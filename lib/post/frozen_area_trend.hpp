// Whether a wall that has not closed ever will: the frozen area followed
// in time. Under strong seepage the heat the water brings balances
// what the pipes take, and the frozen area levels off with a gap still
// open. Steady from day N: the area stays within `band` (1 %) of its last
// value from N on, and grew by less than that over the last fifth of the
// run; otherwise it is still growing, at the last fifth's mean rate.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frostwall::post {

class FrozenAreaTrend {
 public:
  explicit FrozenAreaTrend(double band = 0.01) : band_(band) {}
  void add(double day, double frozen_area);
  // The day the area stopped growing; none while it still grows.
  std::optional<double> steady_since() const;
  // Mean growth over the last fifth of the record, per day, as a share of
  // the last area.
  double recent_growth_per_day() const;
  // "no closure: the frozen area stopped growing (steady state) by day 41",
  // or "no closure by day 120: the frozen area still grows by 0.8 % a day".
  std::string no_closure_verdict() const;

 private:
  double band_;
  std::vector<double> day_, area_;
};

}  // namespace frostwall::post
