#include "project/excavation.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::project {

double HydrationHeat::at(double t) const {
  if (t <= 0.0) return 0.0;
  if (released.empty()) return release_time > 0.0 ? total * -std::expm1(-t / release_time) : total;
  if (t <= released.front().first) return released.front().second * t / released.front().first;
  if (t >= released.back().first) return released.back().second;
  const auto after =
      std::upper_bound(released.begin(), released.end(), t, [](double s, const auto& p) { return s < p.first; });
  const auto before = std::prev(after);
  const double w = (t - before->first) / (after->first - before->first);
  return before->second + w * (after->second - before->second);
}

double HydrationHeat::final() const { return released.empty() ? total : released.back().second; }

double HydrationHeat::end_time() const {
  if (!released.empty()) return released.back().first;
  return release_time * std::log(1e6);  // exp(-t / tau) = 1e-6
}

}  // namespace frostwall::project
