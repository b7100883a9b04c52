#include "freezing/thermometers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include "freezing/output_frames.hpp"
#include "particles/mirror_images.hpp"
#include "particles/symmetry_group.hpp"
#include "post/closure.hpp"

namespace frostwall::freezing {

namespace {

// The particles the snapshot files show, and their mirror images, each
// with the particle whose value it carries.
post::TriangleProbe shown_probe(const project::Project& p, const Model& m) {
  if (p.monitoring.empty()) return post::TriangleProbe({}, {}, {});
  const auto& P = m.particles();
  std::vector<particles::Vec<2>> points;
  std::vector<std::uint32_t> source;
  std::optional<std::array<double, 2>> plate;
  if (const auto* rect = std::get_if<project::Rectangle>(&p.geometry)) plate = std::array{rect->width, rect->height};
  std::vector<char> shown(P.size(), 0);
  for (std::uint32_t i = 0; i < P.size(); ++i)
    if ((shown[i] = shown_in_files(P, i, plate))) points.push_back(P.position[i]), source.push_back(i);
  if (!P.mirrors.empty()) {
    const auto images = m.shaft ? particles::mirror_images(P, 3.0 * P.coarsest_spacing(), post::image_reach(P))
                                : particles::mirror_images(P, 3.0 * P.coarsest_spacing());
    for (std::size_t k = 0; k < images.source.size(); ++k)
      if (shown[images.source[k]]) points.push_back(images.position[k]), source.push_back(images.source[k]);
  }
  return post::TriangleProbe(points, source, sensor_points(p, m));
}

}  // namespace

Thermometers::Thermometers(const project::Project& p, const Model& m)
    : probe_(shown_probe(p, m)),
      tolerance_(p.numerics.sensor_tolerance),
      step_limit_(std::numeric_limits<double>::infinity()) {}

void Thermometers::after_step(const thermal::ThermalModel& m, double t) {
  std::swap(earlier_, before_);
  std::swap(before_, now_);
  now_ = probe_(m.temperature());
  t_earlier_ = t_before_;
  t_before_ = t_now_;
  t_now_ = t;
  seen_ = std::min(seen_ + 1, 3);
  step_limit_ = std::numeric_limits<double>::infinity();
  if (seen_ < 3 || !(t_now_ > t_before_ && t_before_ > t_earlier_)) return;
  for (std::size_t k = 0; k < now_.size(); ++k) {
    const double slope_now = (now_[k] - before_[k]) / (t_now_ - t_before_);
    const double slope_before = (before_[k] - earlier_[k]) / (t_before_ - t_earlier_);
    const double curvature = std::abs(2.0 * (slope_now - slope_before) / (t_now_ - t_earlier_));
    if (curvature > 0.0) step_limit_ = std::min(step_limit_, std::sqrt(8.0 * tolerance_ / curvature));
  }
}

double Thermometers::at(std::size_t k, double tau) const {
  if (seen_ < 2 || !(t_now_ > t_before_)) return now_[k];
  const double w = std::clamp((tau - t_before_) / (t_now_ - t_before_), 0.0, 1.0);
  return before_[k] + w * (now_[k] - before_[k]);
}

std::vector<particles::Vec<2>> sensor_points(const project::Project& p, const Model& m) {
  std::vector<particles::Vec<2>> where;
  if (!m.shaft) {
    for (const auto& s : p.monitoring) where.emplace_back(s.x, s.y);
    return where;
  }
  const auto group = particles::symmetry_group(m.particles().mirrors, m.shaft->far_field_radius);
  for (const auto& s : p.monitoring) {
    particles::Vec<2> x(s.x, s.y), inside = x;
    for (const auto& g : group)
      if (geometry::inside_wedge(m.shaft->wedge, g(x))) {
        inside = g(x);
        break;
      }
    where.push_back(inside);
  }
  return where;
}

}  // namespace frostwall::freezing
