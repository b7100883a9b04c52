#include "post/field_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "particles/mirror_images.hpp"
#include "particles/cell_list.hpp"
#include "sph/laplacian.hpp"
#include "particles/parallel.hpp"

namespace frostwall::post {

struct FieldSampler::Cloud {
  const sph::Kernel* kernel = nullptr;
  double h_max = 0.0;     // the largest smoothing length
  std::vector<double> h;  // per point (of its source)
  std::size_t n_particles = 0;
  std::vector<Vec2> points;           // real particles, then images
  std::vector<std::uint32_t> source;  // particle a point carries the value of
  std::vector<double> volume;         // V of the source
  // Points grouped by smoothing length (each level within a factor 2), one
  // cell list per level sized to its supports: a query near fine particles
  // then scans cells of their size, not of the far field's.
  struct Level {
    double reach = 0.0;  // largest support in the level
    std::vector<Vec2> points;
    std::vector<std::uint32_t> index;  // into the cloud's points
    std::unique_ptr<particles::CellList<2>> cells;
  };
  std::vector<Level> levels;

  // visit(k, r) for every point k whose support reaches x.
  template <class Visit>
  void for_each_reaching(const Vec2& x, Visit&& visit) const {
    for (const auto& level : levels)
      level.cells->for_each_within(x, level.reach, [&](std::uint32_t m, double r) {
        const std::uint32_t k = level.index[m];
        if (r < sph::Kernel::support_factor * h[k]) visit(k, r);
      });
  }
};

FieldSampler::FieldSampler(const particles::ParticleSet<2>& particles, const sph::Kernel& kernel,
                           const sph::SmoothingLengths& h)
    : cloud_(std::make_unique<Cloud>()) {
  if (!(h.smallest() > 0.0)) throw std::invalid_argument("field sampler: smoothing length must be > 0");
  auto& c = *cloud_;
  c.kernel = &kernel;
  c.h_max = h.largest();
  c.n_particles = particles.size();
  const double reach = sph::Kernel::support_factor * c.h_max;
  // mirror_images keeps images within its reach of a free particle; a sample
  // point is up to about a spacing from the nearest free particle (between
  // a wedge side and the first lattice row), so reach further by a spacing
  // or an image at the rim of its support would be missed.
  const double spacing = particles.spacing > 0.0 ? particles.coarsest_spacing() : c.h_max;
  // An image adds to a sample (inside the wedge) only within its own
  // support 2 h_j, so it need not lie further beyond a mirror than that.
  std::vector<double> own_reach(particles.size());
  for (std::size_t j = 0; j < particles.size(); ++j)
    own_reach[j] = sph::Kernel::support_factor * h.of(j) + particles.spacing_of(j);
  const auto images = particles::mirror_images(particles, reach + spacing, own_reach);
  c.points = particles.position;
  c.points.insert(c.points.end(), images.position.begin(), images.position.end());
  c.source.resize(c.points.size());
  for (std::size_t j = 0; j < particles.size(); ++j) c.source[j] = static_cast<std::uint32_t>(j);
  std::copy(images.source.begin(), images.source.end(), c.source.begin() + particles.size());
  c.volume.resize(c.points.size());
  c.h.resize(c.points.size());
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    c.volume[k] = particles.volume[c.source[k]];
    c.h[k] = h.of(c.source[k]);
  }
  const double h_min = h.smallest();
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const auto L = static_cast<std::size_t>(std::max(0.0, std::floor(std::log2(c.h[k] / h_min) + 1e-9)));
    if (c.levels.size() <= L) c.levels.resize(L + 1);
    c.levels[L].points.push_back(c.points[k]);
    c.levels[L].index.push_back(static_cast<std::uint32_t>(k));
    c.levels[L].reach = std::max(c.levels[L].reach, sph::Kernel::support_factor * c.h[k]);
  }
  // (Empty levels go first: a cell list refers to its level's points.)
  std::erase_if(c.levels, [](const Cloud::Level& level) { return level.points.empty(); });
  for (auto& level : c.levels) level.cells = std::make_unique<particles::CellList<2>>(level.points, level.reach);
}

FieldSampler::~FieldSampler() = default;
FieldSampler::FieldSampler(FieldSampler&&) noexcept = default;
FieldSampler& FieldSampler::operator=(FieldSampler&&) noexcept = default;

std::size_t FieldSampler::particle_count() const { return cloud_->n_particles; }
double FieldSampler::support() const { return sph::Kernel::support_factor * cloud_->h_max; }

// A point no support reaches: the shaft axis of a lattice wedge, whose
// apex is too narrow to hold particles (the images round the axis come
// only from particles within reach of it). Its value is the kernel mean of
// the points nearest it, the support stretched to 1.5 times the distance of
// the nearest (a smooth field there: the axis is far from any pipe). Up to
// eight times the largest support; beyond that, nothing.
std::vector<std::pair<std::uint32_t, double>> FieldSampler::widened_weights(const Vec2& x, double& total) const {
  const auto& c = *cloud_;
  std::vector<std::pair<std::uint32_t, double>> w;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& y : c.points) nearest = std::min(nearest, (y - x).norm());
  const double reach = 1.5 * nearest;
  if (!(reach <= 8.0 * support())) return w;
  const double h = reach / sph::Kernel::support_factor;
  for (std::size_t k = 0; k < c.points.size(); ++k) {
    const double wk = c.kernel->value((c.points[k] - x).norm(), h) * c.volume[k];
    if (wk <= 0.0) continue;
    w.emplace_back(c.source[k], wk);
    total += wk;
  }
  return w;
}

std::vector<std::pair<std::uint32_t, double>> FieldSampler::weights(const Vec2& x, bool stretch) const {
  const auto& c = *cloud_;
  std::vector<std::pair<std::uint32_t, double>> w;
  double total = 0.0;
  c.for_each_reaching(x, [&](std::uint32_t k, double r) {
    const double wk = c.kernel->value(r, c.h[k]) * c.volume[k];
    if (wk <= 0.0) return;
    w.emplace_back(c.source[k], wk);
    total += wk;
  });
  if (w.empty() && stretch) w = widened_weights(x, total);
  if (w.empty()) return w;
  // A particle and its images are one value: fold them into one weight.
  std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::size_t out = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    if (out > 0 && w[out - 1].first == w[k].first) w[out - 1].second += w[k].second;
    else w[out++] = w[k];
  }
  w.resize(out);
  for (auto& [j, wj] : w) wj /= total;
  return w;
}

double FieldSampler::value(const Vec2& x, const std::vector<double>& field) const {
  const auto& c = *cloud_;
  if (field.size() != c.n_particles)
    throw std::invalid_argument("field sampler: the field must have one value per particle");
  double sum = 0.0, total = 0.0;
  c.for_each_reaching(x, [&](std::uint32_t k, double r) {
    const double wk = c.kernel->value(r, c.h[k]) * c.volume[k];
    sum += wk * field[c.source[k]];
    total += wk;
  });
  return total > 0.0 ? sum / total : std::numeric_limits<double>::quiet_NaN();
}

std::vector<double> FieldSampler::sample(const std::vector<Vec2>& where, const std::vector<double>& field) const {
  if (field.size() != cloud_->n_particles)
    throw std::invalid_argument("field sampler: the field must have one value per particle");
  std::vector<double> out(where.size());
  particles::for_each_particle(where.size(), [&](std::size_t i) { out[i] = value(where[i], field); });
  return out;
}

PointProbe::PointProbe(const FieldSampler& sampler, std::vector<Vec2> where, bool stretch)
    : where_(std::move(where)), particle_count_(sampler.particle_count()) {
  std::vector<std::vector<std::pair<std::uint32_t, double>>> rows(where_.size());
  particles::for_each_particle(where_.size(), [&](std::size_t i) { rows[i] = sampler.weights(where_[i], stretch); });
  start_.assign(where_.size() + 1, 0);
  for (std::size_t i = 0; i < rows.size(); ++i) start_[i + 1] = start_[i] + rows[i].size();
  index_.reserve(start_.back());
  weight_.reserve(start_.back());
  for (const auto& row : rows)
    for (const auto& [j, w] : row) {
      index_.push_back(j);
      weight_.push_back(w);
    }
}

std::vector<double> PointProbe::operator()(const std::vector<double>& field) const {
  if (field.size() != particle_count_)
    throw std::invalid_argument("point probe: the field must have one value per particle");
  std::vector<double> out(where_.size());
  for (std::size_t i = 0; i < where_.size(); ++i) out[i] = at(i, field);
  return out;
}

double PointProbe::at(std::size_t i, const std::vector<double>& field) const {
  if (start_[i] == start_[i + 1]) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) sum += weight_[e] * field[index_[e]];
  return sum;
}

}  // namespace frostwall::post
