#include "post/wall_extent.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "particles/parallel.hpp"

namespace frostwall::post {

namespace {

constexpr double frozen_level = 0.5;

struct Samples {
  std::vector<double> r, v;
};

// The finite samples, checked for size and order.
Samples finite_samples(const std::vector<double>& r, const std::vector<double>& v, const char* what) {
  if (r.size() != v.size()) throw std::invalid_argument(std::string(what) + ": one value per radius expected");
  for (std::size_t i = 1; i < r.size(); ++i)
    if (!(r[i] > r[i - 1])) throw std::invalid_argument(std::string(what) + ": radii must ascend");
  Samples s;
  for (std::size_t i = 0; i < r.size(); ++i)
    if (std::isfinite(v[i])) {
      s.r.push_back(r[i]);
      s.v.push_back(v[i]);
    }
  return s;
}

// The piecewise-linear interpolant at x, clamped to the end values.
double interpolate(const Samples& s, double x) {
  if (x <= s.r.front()) return s.v.front();
  if (x >= s.r.back()) return s.v.back();
  const std::size_t k = std::upper_bound(s.r.begin(), s.r.end(), x) - s.r.begin();  // r[k-1] <= x < r[k]
  const double t = (x - s.r[k - 1]) / (s.r[k] - s.r[k - 1]);
  return s.v[k - 1] + t * (s.v[k] - s.v[k - 1]);
}

// Where the segment from (ra, fa) to (rb, fb) crosses the level (one end
// at or below it, the other above).
double crossing(double ra, double fa, double rb, double fb, double level) {
  return ra + (level - fa) / (fb - fa) * (rb - ra);
}

}  // namespace

FrozenStretch frozen_stretch(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                             double ring_radius) {
  return stretch_at_or_below(r, liquid_fraction, frozen_level, ring_radius);
}

FrozenStretch stretch_at_or_below(const std::vector<double>& r, const std::vector<double>& values, double level,
                                  double ring_radius) {
  Samples s = finite_samples(r, values, "frozen_stretch");
  FrozenStretch none;
  if (s.r.empty() || !(ring_radius >= s.r.front() && ring_radius <= s.r.back())) return none;
  // Put the ring radius in as a sample: the interpolant is unchanged, and the
  // walk outward from it needs no special first segment.
  const std::size_t m = std::lower_bound(s.r.begin(), s.r.end(), ring_radius) - s.r.begin();
  if (s.r[m] != ring_radius) {
    const double f_ring = interpolate(s, ring_radius);
    s.r.insert(s.r.begin() + m, ring_radius);
    s.v.insert(s.v.begin() + m, f_ring);
  }
  if (s.v[m] > level) return none;

  double inner = s.r.front();
  for (std::size_t i = m; i > 0; --i)
    if (s.v[i - 1] > level) {
      inner = crossing(s.r[i - 1], s.v[i - 1], s.r[i], s.v[i], level);
      break;
    }
  double outer = s.r.back();
  for (std::size_t i = m; i + 1 < s.r.size(); ++i)
    if (s.v[i + 1] > level) {
      outer = crossing(s.r[i], s.v[i], s.r[i + 1], s.v[i + 1], level);
      break;
    }
  return {inner, outer, outer - inner};
}

FrozenStretch frozen_stretch(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                             const std::vector<double>& ring_radii) {
  return stretch_at_or_below(r, liquid_fraction, frozen_level, ring_radii);
}

FrozenStretch stretch_at_or_below(const std::vector<double>& r, const std::vector<double>& values, double level,
                                  const std::vector<double>& ring_radii) {
  FrozenStretch longest;
  for (double ring : ring_radii)
    if (const auto s = stretch_at_or_below(r, values, level, ring);
        s.frozen() && (!longest.frozen() || s.thickness > longest.thickness))
      longest = s;
  return longest;
}

std::optional<double> mean_over_frozen(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                                       const std::vector<double>& temperature, const FrozenStretch& stretch) {
  if (liquid_fraction.size() != r.size())
    throw std::invalid_argument("mean_over_frozen: one liquid fraction per radius expected");
  if (!stretch.frozen()) return std::nullopt;
  const Samples T = finite_samples(r, temperature, "mean_over_frozen");
  if (T.r.empty()) return std::nullopt;
  const double a = *stretch.inner, b = *stretch.outer;
  if (!(b > a)) return interpolate(T, a);
  // Trapezoids over the end points and the samples strictly between them.
  double integral = 0.0, r_prev = a, T_prev = interpolate(T, a);
  for (std::size_t i = 0; i < T.r.size(); ++i) {
    if (T.r[i] <= a || T.r[i] >= b) continue;
    integral += 0.5 * (T_prev + T.v[i]) * (T.r[i] - r_prev);
    r_prev = T.r[i];
    T_prev = T.v[i];
  }
  integral += 0.5 * (T_prev + interpolate(T, b)) * (b - r_prev);
  return integral / (b - a);
}

int RayFan::rays_needed(double angle, double ring_radius, double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("rays_needed: spacing must be > 0");
  const double arcs = std::ceil(angle * ring_radius / spacing - 1e-9);
  if (angle >= 2.0 * std::numbers::pi - 1e-12) return std::max(2, static_cast<int>(arcs));
  return std::max(2, static_cast<int>(arcs) + 1);
}

double RayFan::ray_angle(int k) const {
  if (rays <= 1) return start_angle;
  const bool full_circle = angle >= 2.0 * std::numbers::pi - 1e-12;
  return start_angle + k * angle / (full_circle ? rays : rays - 1);
}

std::vector<double> RayFan::radii() const {
  if (!(dr > 0.0) || !(r_max >= r_min)) throw std::invalid_argument("ray fan: need dr > 0 and r_max >= r_min");
  std::vector<double> r;
  const long n = static_cast<long>(std::floor((r_max - r_min) / dr + 1e-9));
  for (long i = 0; i <= n; ++i) r.push_back(r_min + i * dr);
  if (r.back() < r_max - 1e-9 * dr) r.push_back(r_max);  // the ray always reaches r_max
  return r;
}

std::vector<Vec2> RayFan::points() const {
  const std::vector<double> r = radii();
  std::vector<Vec2> p;
  p.reserve(static_cast<std::size_t>(rays) * r.size());
  for (int k = 0; k < rays; ++k) {
    const double phi = ray_angle(k);
    const Vec2 e(std::cos(phi), std::sin(phi));
    for (double ri : r) p.push_back(ri * e);
  }
  return p;
}

std::vector<double> RayFan::on_ray(const std::vector<double>& fan_values, int k) const {
  const std::size_t n = radii().size();
  if (fan_values.size() != n * static_cast<std::size_t>(rays) || k < 0 || k >= rays)
    throw std::invalid_argument("ray fan: values must be given at every point of the fan");
  return {fan_values.begin() + k * n, fan_values.begin() + (k + 1) * n};
}

WallExtents wall_extents(const RayFan& fan, const std::vector<double>& values_on_fan,
                         const std::vector<double>& ring_radii, double level) {
  const std::vector<double> r = fan.radii();
  WallExtents w;
  w.rays.reserve(fan.rays);
  for (int k = 0; k < fan.rays; ++k) {
    w.rays.push_back(stretch_at_or_below(r, fan.on_ray(values_on_fan, k), level, ring_radii));
    if (k == 0 || w.rays.back().thickness < w.min_thickness) {
      w.min_thickness = w.rays.back().thickness;
      w.thinnest_ray = k;
    }
  }
  return w;
}

WallGauge::WallGauge(const FieldSampler& sampler, RayFan fan, std::vector<double> ring_radii,
                     std::optional<double> isotherm)
    : fan_(fan),
      ring_radii_(std::move(ring_radii)),
      radii_(fan.radii()),
      fan_probe_(sampler, fan.points()),
      isotherm_(isotherm) {}

std::vector<double> WallGauge::read_outward(const std::vector<double>& field, double level,
                                            std::vector<std::pair<std::size_t, std::size_t>>& read) const {
  // A ray's stretches at or below the level need their samples only from
  // each ring outward, on either side, to the first one above it: those are
  // read, the rest stay NaN (skipped as "no particle within reach"). The
  // answer is the same as from every sample, at a fraction of the reads
  // once the wall is thin against the domain.
  const std::size_t n = radii_.size();
  std::vector<double> values(n * fan_.rays, std::numeric_limits<double>::quiet_NaN());
  read.assign(fan_.rays, {n, 0});
  particles::for_each_item(fan_.rays, [&](std::size_t k) {
    double* ray = values.data() + k * n;
    auto above_at = [&](std::size_t i) {  // reads sample i of the ray
      if (std::isnan(ray[i])) ray[i] = fan_probe_.at(k * n + i, field);
      return ray[i] > level;
    };
    for (double ring : ring_radii_) {
      const std::size_t m =
          std::max(first_, std::size_t(std::lower_bound(radii_.begin(), radii_.end(), ring) - radii_.begin()));
      std::size_t first = std::min(m, n - 1), last = first;
      for (std::size_t i = m; i-- > first_;)
        if (first = i; above_at(i)) break;
      for (std::size_t i = m; i < n; ++i)
        if (last = i; above_at(i)) break;
      read[k] = {std::min(read[k].first, first), std::max(read[k].second, last)};
    }
  });
  return values;
}

void WallGauge::set_inner_limit(double r) {
  inner_limit_ = r;
  first_ = std::lower_bound(radii_.begin(), radii_.end(), r) - radii_.begin();
}

void WallGauge::clip(WallExtents& w) const {
  if (!inner_limit_ || first_ >= radii_.size()) return;
  for (std::size_t k = 0; k < w.rays.size(); ++k) {
    auto& s = w.rays[k];
    if (s.frozen() && *s.inner <= radii_[first_] + 1e-12) {
      s.inner = *inner_limit_;
      s.thickness = *s.outer - *inner_limit_;
    }
    if (k == 0 || s.thickness < w.min_thickness) w.min_thickness = s.thickness, w.thinnest_ray = int(k);
  }
}

WallReading WallGauge::measure(const std::vector<double>& liquid_fraction,
                               const std::vector<double>& temperature) const {
  const std::size_t n = radii_.size();
  std::vector<std::pair<std::size_t, std::size_t>> read;  // [first, last] index read per ray
  const std::vector<double> f = read_outward(liquid_fraction, frozen_level, read);
  WallReading reading;
  reading.extents = wall_extents(fan_, f, ring_radii_);
  clip(reading.extents);
  // The mean temperature over ray k's frozen stretch, from T where f was read.
  auto mean_temperature_on = [&](int k) {
    std::vector<double> T(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = read[k].first; i <= read[k].second && i < n; ++i) T[i] = fan_probe_.at(k * n + i, temperature);
    return mean_over_frozen(radii_, fan_.on_ray(f, k), T, reading.extents.rays[std::size_t(k)]);
  };
  const int OB = fan_.rays - 1, thinnest = reading.extents.thinnest_ray;
  reading.mean_temperature_OB = mean_temperature_on(OB);
  reading.mean_temperature_thinnest = thinnest == OB ? reading.mean_temperature_OB : mean_temperature_on(thinnest);
  if (isotherm_) {  // the wall colder than the isotherm: the same reading on temperature
    const std::vector<double> T_fan = read_outward(temperature, *isotherm_, read);
    reading.isotherm = wall_extents(fan_, T_fan, ring_radii_, *isotherm_);
    clip(reading.isotherm);
    const std::vector<double> ray = fan_.on_ray(T_fan, reading.isotherm.thinnest_ray);
    reading.isotherm_mean_temperature =
        mean_over_frozen(radii_, ray, ray, reading.isotherm.rays[std::size_t(reading.isotherm.thinnest_ray)]);
  }
  return reading;
}

double weakest_angle(const RayFan& fan, const WallExtents& e) {
  const int n = static_cast<int>(e.rays.size());
  if (n == 0) return fan.start_angle;
  if (e.min_thickness > 0.0) return fan.ray_angle(e.thinnest_ray);
  const bool circle = fan.angle >= 2.0 * std::numbers::pi - 1e-12;
  // Longest run of unfrozen rays; on a full circle it may wrap past ray 0.
  int best_start = -1, best_length = 0;
  const int span = circle ? 2 * n : n;
  for (int start = 0, k = 0; k < span; ++k) {
    const bool open = !e.rays[k % n].frozen();
    if (!open) {
      start = k + 1;
      continue;
    }
    const int length = std::min(k - start + 1, n);
    if (length > best_length) best_length = length, best_start = start;
  }
  if (best_start < 0) return fan.ray_angle(e.thinnest_ray);
  const double middle = best_start + 0.5 * (best_length - 1);
  return fan.start_angle + (circle ? middle * fan.angle / n : middle * fan.angle / std::max(1, n - 1));
}

}  // namespace frostwall::post
