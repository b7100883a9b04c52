#include "run/error_law.hpp"

#include <cmath>
#include <limits>

namespace frostwall::run {

namespace {
constexpr double unknown = std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> series_errors(const std::vector<double>& fine, const std::vector<std::vector<double>>& coarse,
                                  double ratio, double order) {
  const std::size_t n = fine.size();
  std::vector<double> error(n, unknown);
  if (coarse.size() < 2) return error;  // no scatter from fewer than two twins
  for (const auto& c : coarse)
    if (c.size() != n) return error;
  // One sign for every change of the series, else no Richardson reduction.
  bool up = false, down = false;
  for (std::size_t t = 0; t < n; ++t)
    for (const auto& c : coarse) {
      const double d = c[t] - fine[t];
      up = up || d > 0.0;
      down = down || d < 0.0;
    }
  const double scale = up && down ? 1.0 : 1.0 / (std::pow(ratio, order) - 1.0);
  const double K = static_cast<double>(coarse.size());
  for (std::size_t t = 0; t < n; ++t) {
    double mean = 0.0;
    bool known = std::isfinite(fine[t]);
    for (const auto& c : coarse) known = known && std::isfinite(c[t]), mean += c[t] / K;
    if (!known) continue;
    double squares = 0.0;
    for (const auto& c : coarse) squares += (c[t] - mean) * (c[t] - mean);
    error[t] = scale * std::abs(mean - fine[t]) + std::sqrt(squares / (K - 1.0));
  }
  return error;
}

double number_error(double fine, const std::vector<double>& coarse, double ratio, double order) {
  std::vector<std::vector<double>> series;
  for (double c : coarse) series.push_back({c});
  return series_errors({fine}, series, ratio, order).front();
}

}  // namespace frostwall::run
