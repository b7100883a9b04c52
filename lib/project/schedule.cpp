// Time-dependent wall temperatures, the time unit of the project file, the
// pipe models' names.
#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "project/project.hpp"
#include "project/units.hpp"

namespace frostwall::project {

double TemperatureSchedule::at(double t_seconds) const {
  // The loader never produces an empty schedule; one here is a programming error.
  if (points.empty()) throw std::logic_error("TemperatureSchedule::at: no points");
  if (t_seconds <= points.front().first) return points.front().second;
  if (t_seconds >= points.back().first) return points.back().second;
  // Strictly inside: `after` exists and lies later than `before`.
  const auto after =
      std::upper_bound(points.begin(), points.end(), t_seconds, [](double t, const auto& p) { return t < p.first; });
  const auto before = std::prev(after);
  const double w = (t_seconds - before->first) / (after->first - before->first);
  return before->second + w * (after->second - before->second);
}

double TimeSettings::unit_seconds() const {
  switch (unit) {
    case TimeUnit::s: return 1.0;
    case TimeUnit::h: return 3600.0;
    case TimeUnit::d: return seconds_per_day;
  }
  return 1.0;  // unreachable; keeps -Wreturn-type quiet
}

const char* TimeSettings::unit_name() const { return unit == TimeUnit::s ? "s" : (unit == TimeUnit::h ? "h" : "d"); }

const char* pipe_model_name(PipeModel model) {
  switch (model) {
    case PipeModel::disc: return "resolved";
    case PipeModel::line: return "line";
    case PipeModel::point: return "point";
  }
  return "resolved";  // unreachable; keeps -Wreturn-type quiet
}

}  // namespace frostwall::project
