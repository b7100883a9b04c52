#include "post/frozen_area_trend.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

namespace frostwall::post {

void FrozenAreaTrend::add(double day, double frozen_area) {
  day_.push_back(day);
  area_.push_back(frozen_area);
}

namespace {
// The first record at or after the last fifth of the time span.
std::size_t last_fifth(const std::vector<double>& day) {
  const double from = day.back() - 0.2 * (day.back() - day.front());
  return std::size_t(std::lower_bound(day.begin(), day.end(), from) - day.begin());
}
}  // namespace

double FrozenAreaTrend::recent_growth_per_day() const {
  if (day_.size() < 2 || area_.back() <= 0.0) return 0.0;
  const std::size_t k = std::min(last_fifth(day_), day_.size() - 2);
  return (area_.back() - area_[k]) / (day_.back() - day_[k]) / area_.back();
}

std::optional<double> FrozenAreaTrend::steady_since() const {
  if (day_.size() < 2 || area_.back() <= 0.0) return std::nullopt;
  const double last = area_.back(), tolerance = band_ * last;
  if (last - area_[last_fifth(day_)] > tolerance) return std::nullopt;  // still growing
  std::size_t k = day_.size() - 1;
  while (k > 0 && std::abs(last - area_[k - 1]) <= tolerance) --k;
  if (k == 0) return day_.front();
  // Interpolate where the area entered the band.
  const double a = area_[k - 1], b = area_[k], enter = area_[k - 1] < last ? last - tolerance : last + tolerance;
  return day_[k - 1] + (enter - a) / (b - a) * (day_[k] - day_[k - 1]);
}

std::string FrozenAreaTrend::no_closure_verdict() const {
  if (const auto since = steady_since())
    return fmt::format("no closure: the frozen area stopped growing (steady state) by day {:.0f}", std::ceil(*since));
  return fmt::format("no closure by day {:.0f}: the frozen area still grows by {:.2g} % a day",
                     day_.empty() ? 0.0 : day_.back(), 100.0 * recent_growth_per_day());
}

}  // namespace frostwall::post
