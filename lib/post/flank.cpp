#include "post/flank.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frostwall::post {

namespace {

// Walking from the peak by `step` (+1 or -1): where f first falls through `level`.
std::optional<double> crossing(const std::vector<double>& x, const std::vector<double>& f, std::size_t peak, int step,
                               double level) {
  for (long i = static_cast<long>(peak); i + step >= 0 && i + step < static_cast<long>(f.size()); i += step) {
    const double a = f[i], b = f[i + step];
    if (b <= level) return x[i] + (x[i + step] - x[i]) * (a - level) / (a - b);
  }
  return std::nullopt;
}

std::optional<Flank> flank(const std::vector<double>& x, const std::vector<double>& f, std::size_t peak, int step,
                           double low, double high) {
  const double p = f[peak];
  const auto x90 = crossing(x, f, peak, step, high * p);
  const auto x10 = crossing(x, f, peak, step, low * p);
  if (!x90 || !x10 || *x10 == *x90) return std::nullopt;
  Flank fl;
  fl.x10 = *x10, fl.x90 = *x90;
  const double run = std::abs(*x10 - *x90);
  fl.slope_deg = std::atan2((high - low) * p, run) * 180.0 / std::numbers::pi;
  // The line through both points, down to f = 0 beyond x10.
  fl.foot = *x10 + (*x10 - *x90) * low / (high - low);
  return fl;
}

}  // namespace

std::optional<double> Bump::width() const {
  if (!low_side || !high_side) return std::nullopt;
  return high_side->foot - low_side->foot;
}

std::optional<double> Bump::mean_slope_deg() const {
  if (low_side && high_side) return 0.5 * (low_side->slope_deg + high_side->slope_deg);
  if (low_side) return low_side->slope_deg;
  if (high_side) return high_side->slope_deg;
  return std::nullopt;
}

Bump bump_flanks(const std::vector<double>& x, const std::vector<double>& profile, double low, double high) {
  Bump b;
  if (profile.empty() || x.size() != profile.size()) return b;
  b.base = *std::min_element(profile.begin(), profile.end());
  std::vector<double> f;
  for (double v : profile) f.push_back(v - b.base);
  std::size_t peak = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f[i] > f[peak]) peak = i;
  b.peak = f[peak], b.peak_x = x[peak];
  if (!(b.peak > 0.0)) return b;
  b.low_side = flank(x, f, peak, -1, low, high);
  b.high_side = flank(x, f, peak, +1, low, high);
  return b;
}

}  // namespace frostwall::post
