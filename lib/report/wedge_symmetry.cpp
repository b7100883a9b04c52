#include "report/wedge_symmetry.hpp"

#include <cmath>
#include <numbers>

namespace frostwall::report {

using Vec2 = particles::Vec<2>;

Vec2 WedgeSymmetry::fold(const Vec2& x) const {
  if (mirror_lines <= 0) return x;
  const double r = x.norm();
  if (r == 0.0) return x;
  // Mirror lines sit at start + k pi/M: fold the angle into one period of
  // 2 pi/M, then reflect the second half onto the first.
  const double period = 2 * std::numbers::pi / mirror_lines;
  double phi = std::fmod(std::atan2(x[1], x[0]) - start, period);
  if (phi < 0) phi += period;
  if (phi > 0.5 * period) phi = period - phi;
  return Vec2(r * std::cos(start + phi), r * std::sin(start + phi));
}

Vec2 WedgeSymmetry::apply(std::size_t copy, const Vec2& x) const {
  if (mirror_lines <= 0 || copy == 0) return x;
  const std::size_t M = static_cast<std::size_t>(mirror_lines);
  if (copy < M) {  // rotation by 2 pi k / M
    const double a = 2 * std::numbers::pi * double(copy) / double(M);
    return Vec2(std::cos(a) * x[0] - std::sin(a) * x[1], std::sin(a) * x[0] + std::cos(a) * x[1]);
  }
  // reflection across the mirror line at start + k pi / M
  const double a = 2 * (start + std::numbers::pi * double(copy - M) / double(M));
  return Vec2(std::cos(a) * x[0] + std::sin(a) * x[1], std::sin(a) * x[0] - std::cos(a) * x[1]);
}

}  // namespace frostwall::report
