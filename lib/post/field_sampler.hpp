// Values of a particle field at arbitrary points (rays through the wall,
// monitoring points): Shepard-normalised SPH interpolation
//     v(x) = sum_j W(x - x_j) V_j v_j / sum_j W(x - x_j) V_j
// over the real particles (free and fixed) and their mirror images, an
// image carrying its source's value. The images make a symmetric field
// look the same near a wedge side as in the interior; the normalisation
// makes the sum a weighted mean, so a liquid fraction stays in [0, 1] and
// a constant is exact everywhere, also next to pipes and holes. A linear
// field is exact where the neighbourhood is point-symmetric about x (at a
// lattice particle, a cell centre, a bond midpoint); elsewhere the lattice
// first moment leaves an error far below a spacing (see the [wall] tests).
//
// Nothing field-specific is stored, so one sampler serves temperature and
// liquid fraction at every snapshot. A point with no particle within the
// support 2h gets NaN. On a graded cloud each particle has its own h_j.
#pragma once

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "sph/kernel.hpp"
#include "particles/particle_set.hpp"
#include "sph/smoothing_lengths.hpp"
#include "particles/vec.hpp"

namespace frostwall::post {

using Vec2 = particles::Vec<2>;

class FieldSampler {
 public:
  // The kernel must outlive the sampler; the particle set need not.
  // h: one smoothing length, or one per particle (a graded cloud: each
  // particle spreads its value over its own support, W(x - x_j, h_j)).
  FieldSampler(const particles::ParticleSet<2>& particles, const sph::Kernel& kernel, const sph::SmoothingLengths& h);
  ~FieldSampler();
  FieldSampler(FieldSampler&&) noexcept;
  FieldSampler& operator=(FieldSampler&&) noexcept;

  // Number of values a field must have (all particles, free then fixed).
  std::size_t particle_count() const;
  double support() const;  // 2h (graded: the largest)

  // field has one value per particle; throws std::invalid_argument otherwise.
  double value(const Vec2& x, const std::vector<double>& field) const;
  std::vector<double> sample(const std::vector<Vec2>& where, const std::vector<double>& field) const;

  // The normalised weights at x, (particle index, weight) summing to one,
  // images folded onto their source; empty when nothing is within reach.
  // With `stretch`, a point no support reaches (the axis of a lattice
  // wedge, whose narrow apex holds no particle) takes the nearest points
  // with a stretched support; empty only when even those are further than
  // 8 times the largest support (a search over all points: for profiles,
  // not for rasters).
  std::vector<std::pair<std::uint32_t, double>> weights(const Vec2& x, bool stretch = false) const;

 private:
  std::vector<std::pair<std::uint32_t, double>> widened_weights(const Vec2& x, double& total) const;
  struct Cloud;
  std::unique_ptr<Cloud> cloud_;  // heap-held: the cell list refers to its points
};

// A fixed set of sample points (the rays, sampled at every snapshot) with
// their weights stored sparsely: each evaluation is one dot product per
// point. Independent of the sampler once built.
class PointProbe {
 public:
  // stretch: see FieldSampler::weights.
  PointProbe(const FieldSampler& sampler, std::vector<Vec2> where, bool stretch = false);

  const std::vector<Vec2>& points() const { return where_; }
  std::size_t size() const { return where_.size(); }
  // NaN at points with no particle within reach.
  std::vector<double> operator()(const std::vector<double>& field) const;
  // The value at point i alone (NaN as above), for readers that need few.
  double at(std::size_t i, const std::vector<double>& field) const;

 private:
  std::vector<Vec2> where_;
  std::size_t particle_count_ = 0;
  std::vector<std::size_t> start_;  // CSR rows, one per point
  std::vector<std::uint32_t> index_;
  std::vector<double> weight_;
};

}  // namespace frostwall::post
