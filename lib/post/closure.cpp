#include "post/closure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "particles/mirror_images.hpp"
#include "particles/cell_list.hpp"

namespace frostwall::post {

ClosureDetector::ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free, double spacing,
                                 double far_field_radius) {
  const std::vector<particles::Vec<2>> free(position.begin(), position.begin() + n_free);
  const double link = 1.5 * spacing;
  const particles::CellList<2> cells(free, link);
  std::vector<char> far_field(n_free, 0);
  std::vector<std::uint32_t> row;
  for (std::size_t i = 0; i < n_free; ++i) {
    row.clear();
    cells.for_each_within(free[i], link, [&](std::uint32_t j, double) {
      if (j != i) row.push_back(j);
    });
    links_.add_row(row);
    far_field[i] = free[i].norm() > far_field_radius - link;
  }
  set_ends(free, std::move(far_field));
}

ClosureDetector::ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free,
                                 const std::vector<double>& local_spacing, double far_field_radius,
                                 const std::vector<particles::Vec<2>>& image_position,
                                 const std::vector<std::uint32_t>& image_source) {
  // Point k at where[k], carrying the value of free particle source[k]:
  // the free particles first, then the images of free particles.
  std::vector<particles::Vec<2>> where(position.begin(), position.begin() + n_free);
  std::vector<std::uint32_t> source(n_free);
  for (std::size_t i = 0; i < n_free; ++i) source[i] = static_cast<std::uint32_t>(i);
  for (std::size_t k = 0; k < image_position.size(); ++k)
    if (image_source[k] < n_free) {
      where.push_back(image_position[k]);
      source.push_back(image_source[k]);
    }
  links_ = delaunay_links(where, source, n_free, local_spacing);
  std::vector<char> far_field(n_free, 0);
  for (std::size_t i = 0; i < n_free; ++i)
    far_field[i] = position[i].norm() > far_field_radius - 1.5 * local_spacing[i];
  where.resize(n_free);
  set_ends(where, std::move(far_field));
}

void ClosureDetector::set_ends(const std::vector<particles::Vec<2>>& free, std::vector<char> far_field) {
  std::uint32_t axis = 0;
  for (std::size_t i = 0; i < free.size(); ++i)
    if (free[i].norm() < free[axis].norm()) axis = static_cast<std::uint32_t>(i);
  ends_ = std::move(far_field);
  if (!ends_.empty()) ends_[axis] |= axis_bit;
}

std::vector<double> image_reach(const particles::ParticleSet<2>& particles) {
  std::vector<double> reach;
  if (!particles.graded()) return reach;
  reach.resize(particles.size());
  for (std::size_t j = 0; j < particles.size(); ++j) reach[j] = 4.5 * particles.spacing_of(j);
  return reach;
}

namespace {
ClosureDetector graded_detector(const particles::ParticleSet<2>& particles, double far_field_radius) {
  const auto images = particles::mirror_images(particles, 3.0 * particles.coarsest_spacing(), image_reach(particles));
  return ClosureDetector(particles.position, particles.n_free, particles.local_spacing, far_field_radius,
                         images.position, images.source);
}
}  // namespace

ClosureDetector::ClosureDetector(const particles::ParticleSet<2>& particles, double far_field_radius)
    : ClosureDetector(particles.graded() ? graded_detector(particles, far_field_radius)
                                         : ClosureDetector(particles.position, particles.n_free, particles.spacing,
                                                           far_field_radius)) {}

double ClosureDetector::bottleneck(const std::vector<double>& f) const {
  // Kruskal-like: add particles from the most liquid down, joining linked
  // ones; the level at which the axis first shares a component with the
  // far field is the bottleneck.
  std::vector<std::uint32_t> order(links_.nodes());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return f[a] > f[b]; });
  ComponentJoin join;
  const auto last = join.first_holding(links_, order, ends_, far_field_bit | axis_bit);
  return last ? f[*last] : -std::numeric_limits<double>::infinity();  // nothing joins them at any level
}

void ClosureWatch::observe(double t, const std::vector<double>& g, double min_interval) {
  if (!due(t)) return;
  next_check_ = t + min_interval;
  const double b = detector_.bottleneck(g);
  // Linear in time between the last observation above a level and this one.
  auto crossing = [&](double level) {
    return b_prev_ > b && std::isfinite(b) ? t_prev_ + (b_prev_ - level) / (b_prev_ - b) * (t - t_prev_) : t;
  };
  if (!contact_ && b <= contact_level) contact_ = crossing(contact_level);
  if (b <= closure_level) {
    closure_ = crossing(closure_level);
    return;
  }
  if (t > t_prev_) rate_ = (b_prev_ - b) / (t - t_prev_);
  t_prev_ = t;
  b_prev_ = b;
}

}  // namespace frostwall::post
