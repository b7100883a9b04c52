#include "project/excavation.hpp"

#include <cmath>

namespace frostwall::project {

double HydrationHeat::at(double t) const {
  if (t <= 0.0) return 0.0;
  if (!released.points.empty()) return released.at(t);
  return release_time > 0.0 ? total * -std::expm1(-t / release_time) : total;
}

double HydrationHeat::final() const { return released.points.empty() ? total : released.points.back().second; }

double HydrationHeat::end_time() const {
  if (!released.points.empty()) return released.points.back().first;
  return release_time * std::log(1e6);  // exp(-t / tau) = 1e-6
}

}  // namespace frostwall::project
