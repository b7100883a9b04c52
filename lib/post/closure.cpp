#include "post/closure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "particles/mirror_images.hpp"
#include "geometry/delaunay.hpp"
#include "particles/cell_list.hpp"

namespace frostwall::post {

ClosureDetector::ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free, double spacing,
                                 double far_field_radius) {
  const std::vector<particles::Vec<2>> free(position.begin(), position.begin() + n_free);
  const double link = 1.5 * spacing;
  const particles::CellList<2> cells(free, link);
  start_.assign(n_free + 1, 0);
  far_field_.assign(n_free, 0);
  for (std::size_t i = 0; i < n_free; ++i) {
    cells.for_each_within(free[i], link, [&](std::uint32_t j, double) {
      if (j != i) link_.push_back(j);
    });
    start_[i + 1] = link_.size();
    far_field_[i] = free[i].norm() > far_field_radius - link;
    if (free[i].norm() < free[axis_].norm()) axis_ = static_cast<std::uint32_t>(i);
  }
}

ClosureDetector::ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free,
                                 const std::vector<double>& local_spacing, double far_field_radius,
                                 const std::vector<particles::Vec<2>>& image_position,
                                 const std::vector<std::uint32_t>& image_source) {
  // Vertex k at where[k], carrying the value of free particle source[k]:
  // the free particles first, then the images of free particles.
  std::vector<std::pair<geometry::Kernel2::Point_2, std::size_t>> points;
  std::vector<particles::Vec<2>> where(position.begin(), position.begin() + n_free);
  std::vector<std::uint32_t> source(n_free);
  for (std::size_t i = 0; i < n_free; ++i) source[i] = static_cast<std::uint32_t>(i);
  for (std::size_t k = 0; k < image_position.size(); ++k)
    if (image_source[k] < n_free) {
      where.push_back(image_position[k]);
      source.push_back(image_source[k]);
    }
  for (std::size_t k = 0; k < where.size(); ++k)
    points.emplace_back(geometry::Kernel2::Point_2(where[k][0], where[k][1]), k);
  const geometry::IndexedDelaunay dt(points.begin(), points.end());
  std::vector<std::vector<std::uint32_t>> near(n_free);
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const std::size_t a = e->first->vertex(dt.cw(e->second))->info();
    const std::size_t b = e->first->vertex(dt.ccw(e->second))->info();
    if (a >= n_free && b >= n_free) continue;  // between two images: a copy of an edge at the real particles
    const std::uint32_t i = source[a], j = source[b];
    if (i == j) continue;
    if ((where[a] - where[b]).norm() > 3.0 * std::max(local_spacing[i], local_spacing[j])) continue;
    near[i].push_back(j);
    near[j].push_back(i);
  }
  start_.assign(n_free + 1, 0);
  far_field_.assign(n_free, 0);
  for (std::size_t i = 0; i < n_free; ++i) {
    std::sort(near[i].begin(), near[i].end());
    near[i].erase(std::unique(near[i].begin(), near[i].end()), near[i].end());
    link_.insert(link_.end(), near[i].begin(), near[i].end());
    start_[i + 1] = link_.size();
    far_field_[i] = position[i].norm() > far_field_radius - 1.5 * local_spacing[i];
    if (position[i].norm() < position[axis_].norm()) axis_ = static_cast<std::uint32_t>(i);
  }
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
  // ones (union-find); the level at which the axis first shares a component
  // with the far field is the bottleneck.
  const std::size_t n = start_.size() - 1;
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return f[a] > f[b]; });
  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<char> added(n, 0), reaches_far(n, 0), holds_axis(n, 0);
  auto root = [&](std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (std::uint32_t i : order) {
    added[i] = 1;
    reaches_far[i] = far_field_[i];
    holds_axis[i] = i == axis_;
    std::uint32_t ri = i;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const std::uint32_t j = link_[e];
      if (!added[j]) continue;
      const std::uint32_t rj = root(j);
      if (rj == ri) continue;
      parent[rj] = ri;
      reaches_far[ri] |= reaches_far[rj];
      holds_axis[ri] |= holds_axis[rj];
    }
    if (reaches_far[ri] && holds_axis[ri]) return f[i];
  }
  return -std::numeric_limits<double>::infinity();  // nothing joins them at any level
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
