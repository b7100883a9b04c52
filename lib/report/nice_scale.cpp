#include "report/nice_scale.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

namespace frostwall::report {

namespace {

// Heckbert's nice number: 1, 2, 5 or 10 times a power of ten.
double nice_number(double x, bool round) {
  const double e = std::floor(std::log10(x));
  const double f = x / std::pow(10.0, e);
  double nf;
  if (round) nf = f < 1.5 ? 1 : (f < 3 ? 2 : (f < 7 ? 5 : 10));
  else nf = f <= 1 ? 1 : (f <= 2 ? 2 : (f <= 5 ? 5 : 10));
  return nf * std::pow(10.0, e);
}

void widen_if_flat(double& lo, double& hi) {
  if (!(hi > lo)) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }
}

int decimals_for(double step) { return std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9))); }

}  // namespace

NiceScale nice_scale(double lo, double hi, int target) {
  widen_if_flat(lo, hi);
  NiceScale s;
  s.step = nice_number(nice_number(hi - lo, false) / std::max(1, target), true);
  s.lo = std::floor(lo / s.step + 1e-9) * s.step;
  s.hi = std::ceil(hi / s.step - 1e-9) * s.step;
  for (double v = s.lo; v <= s.hi + 0.5 * s.step; v += s.step)
    s.ticks.push_back(std::abs(v) < 1e-12 * s.step ? 0.0 : v);
  s.decimals = decimals_for(s.step);
  return s;
}

NiceScale tight_scale(double lo, double hi) {
  widen_if_flat(lo, hi);
  NiceScale best = nice_scale(lo, hi, 4);
  for (int target = 5; target <= 8; ++target) {
    NiceScale s = nice_scale(lo, hi, target);
    if (s.ticks.size() >= 4 && (s.hi - s.lo) < (best.hi - best.lo) * (1 - 1e-9)) best = std::move(s);
  }
  return best;
}

NiceScale ticks_within(double lo, double hi, int target) {
  widen_if_flat(lo, hi);
  NiceScale s;
  s.lo = lo;
  s.hi = hi;
  s.step = nice_number(nice_number(hi - lo, false) / std::max(1, target), true);
  for (double v = std::ceil(lo / s.step - 1e-9) * s.step; v <= hi + 1e-9 * s.step; v += s.step)
    s.ticks.push_back(std::abs(v) < 1e-12 * s.step ? 0.0 : v);
  s.decimals = decimals_for(s.step);
  return s;
}

std::string tick_label(double v, int decimals) {
  std::string text = fmt::format("{:.{}f}", v, decimals);
  if (text.find_first_not_of("-0.") == std::string::npos)
    return decimals > 0 ? fmt::format("{:.{}f}", 0.0, decimals) : "0";
  if (text[0] == '-') text = "\u2212" + text.substr(1);
  return text;
}

std::string with_error(double value, double error, int decimals) {
  if (!std::isfinite(value)) return "–";
  if (!std::isfinite(error) || !(error > 0.0)) return tick_label(value, decimals);
  const int first = static_cast<int>(std::floor(std::log10(error)));
  const bool starts_with_one = error / std::pow(10.0, first) < 2.0;
  const int places = std::clamp(-first + (starts_with_one ? 1 : 0), 0, 6);
  return tick_label(value, places) + " ± " + tick_label(error, places);
}

}  // namespace frostwall::report
