#include "sph/laplacian.hpp"

#include <Eigen/Dense>
#include <deque>
#include <stdexcept>

#include "particles/mirror_images.hpp"
#include "particles/cell_list.hpp"
#include "sph/moment_correction.hpp"
#include "particles/parallel.hpp"
#include "particles/symmetry_group.hpp"

namespace frostwall::sph {

using particles::Vec;
using particles::ParticleSet;
using particles::CellList;
using particles::for_each_particle;
using particles::mirror_images;
using particles::MirrorImages;

namespace {

// The moment correction of the renormalised pairs, each pair seen from i
// (x_j an image or the particle itself, with the map to that image).
template <int Dim>
void correct_moments_on_images(LaplacianPairs& pairs, const ParticleSet<Dim>& particles,
                               const MirrorImages<Dim>& images, const std::vector<Vec<Dim>>& points,
                               const std::vector<std::uint32_t>& entry_point, const SmoothingLengths& h) {
  const std::size_t n = particles.n_free, nnz = pairs.column.size();
  std::vector<Vec<Dim>> pair_vector(nnz);  // x_j - x_i, j as the pair sees it (an image or the particle)
  std::vector<Eigen::Matrix<double, Dim, Dim>> to_image(nnz, Eigen::Matrix<double, Dim, Dim>::Identity());
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      const std::uint32_t k = entry_point[e];
      pair_vector[e] = points[k] - particles.position[i];
      if (k >= particles.size()) to_image[e] = images.linear[k - particles.size()];
    }
  std::vector<double> scale(n);
  for (std::size_t i = 0; i < n; ++i) scale[i] = h.of(i);
  const auto report =
      correct_pair_moments<Dim>(pairs, particles.position, particles.volume, pair_vector, to_image, scale);
  pairs.moments_corrected = report.corrected;
  pairs.smallest_weight_factor = report.smallest_factor;
  pairs.largest_weight_factor = report.largest_factor;
}

// The own-image pairs carry no flux (T_i - T_i): dropped once the moments are set.
template <int Dim>
void drop_own_images(LaplacianPairs& pairs, const LaplacianOptions& options) {
  const std::size_t n = pairs.n_free;
  std::size_t out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t begin = pairs.row_start[i], end = pairs.row_start[i + 1];
    pairs.row_start[i] = out;
    for (std::size_t e = begin; e < end; ++e) {
      if (pairs.column[e] == i) continue;
      pairs.column[out] = pairs.column[e];
      pairs.weight[out] = pairs.weight[e];
      if (options.keep_directions)
        for (int d = 0; d < Dim; ++d) pairs.direction2[out * Dim + d] = pairs.direction2[e * Dim + d];
      if (options.keep_vectors)
        for (int d = 0; d < Dim; ++d) pairs.vector[out * Dim + d] = pairs.vector[e * Dim + d];
      ++out;
    }
  }
  pairs.row_start[n] = out;
  pairs.column.resize(out);
  pairs.weight.resize(out);
  if (options.keep_directions) pairs.direction2.resize(out * Dim);
  if (options.keep_vectors) pairs.vector.resize(out * Dim);
}

}  // namespace

template <int Dim>
LaplacianPairs build_laplacian_pairs(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                     const LaplacianOptions& options) {
  const SmoothingLengths& h = options.h;
  const double h_max = h.largest();
  const double reach = Kernel::support_factor * h_max;

  // Every point a free particle can see: real particles, then mirror images.
  const MirrorImages<Dim> images = mirror_images(particles, reach);
  std::vector<Vec<Dim>> points = particles.position;
  std::vector<std::uint32_t> source(particles.size());
  for (std::size_t j = 0; j < particles.size(); ++j) source[j] = static_cast<std::uint32_t>(j);
  points.insert(points.end(), images.position.begin(), images.position.end());
  source.insert(source.end(), images.source.begin(), images.source.end());
  // Cells of the smallest support: a query of a larger one spans more cells.
  const CellList<Dim> cells(points, Kernel::support_factor * h.smallest());

  LaplacianPairs pairs;
  pairs.dim = Dim;
  pairs.n_free = particles.n_free;
  const std::size_t n = particles.n_free;
  pairs.renormalisation.assign(n, 1.0);

  // Neighbours of i: within 2 h_ij = h_i + h_j (a lattice: 2h). F_ij with
  // eta = 0.1 h_ij, which keeps it finite at tiny r.
  auto for_each_neighbour = [&](std::size_t i, auto&& visit) {
    const double hi = h.of(i);
    cells.for_each_within(particles.position[i], hi + h_max, [&](std::uint32_t k, double r) {
      if (r == 0.0) return;
      const std::uint32_t j = source[k];
      const double hij = h.pair(i, j);
      if (r >= Kernel::support_factor * hij) return;
      const double F = kernel.derivative(r, hij) * r / (r * r + 0.01 * hij * hij);
      visit(k, j, r, F);
    });
  };

  // First pass: neighbours per row (to size the CSR) and the moment sums.
  std::vector<std::size_t> count(n, 0);
  std::vector<char> lonely(n, 0);  // no neighbour at all: a geometry error
  for_each_particle(n, [&](std::size_t i) {
    double moment = 0.0;  // sum_j V_j F_ij |r_ij|^2, continuum value -Dim
    std::size_t c = 0, others = 0;
    for_each_neighbour(i, [&](std::uint32_t, std::uint32_t j, double r, double F) {
      moment += particles.volume[j] * F * r * r;
      // A particle's own image carries no flux (T_i - T_i); the moment
      // correction counts it while it sets the moments, then drops it.
      if (j != i || options.correct_moments) ++c;
      if (j != i) ++others;
    });
    if (others == 0) lonely[i] = 1;  // only its own images: it would exchange no heat
    count[i] = c;
    if (options.form == project::LaplacianForm::renormalised) {
      if (moment < 0.0) pairs.renormalisation[i] = -static_cast<double>(Dim) / moment;
      else lonely[i] = 1;
    }
  });
  for (std::size_t i = 0; i < n; ++i)
    if (lonely[i])
      throw std::runtime_error(
          "a particle has no neighbour within the kernel support (other than its own mirror images)");

  pairs.row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) pairs.row_start[i + 1] = pairs.row_start[i] + count[i];
  const std::size_t nnz = pairs.row_start[n];
  pairs.column.resize(nnz);
  pairs.weight.resize(nnz);
  if (options.keep_directions) pairs.direction2.resize(nnz * Dim);
  if (options.keep_vectors) pairs.vector.resize(nnz * Dim);

  // Second pass: the stored weights G_ij.
  std::vector<std::uint32_t> entry_point;  // the point (real or image) of each pair, for the moment correction
  if (options.correct_moments) entry_point.resize(nnz);
  for_each_particle(n, [&](std::size_t i) {
    std::size_t e = pairs.row_start[i];
    const Vec<Dim>& xi = particles.position[i];
    const double ci = pairs.renormalisation[i];
    for_each_neighbour(i, [&](std::uint32_t k, std::uint32_t j, double r, double F) {
      if (j == i && !options.correct_moments) return;
      // A fixed particle has no equation of its own: its side uses c_i only.
      const double s = j < n ? 0.5 * (ci + pairs.renormalisation[j]) : ci;
      pairs.column[e] = j;
      pairs.weight[e] = -particles.volume[j] * F * s;
      if (options.correct_moments) entry_point[e] = k;
      if (options.keep_directions) {
        const Vec<Dim> rij = xi - points[k];
        for (int d = 0; d < Dim; ++d) pairs.direction2[e * Dim + d] = rij[d] * rij[d] / (r * r);
      }
      if (options.keep_vectors)
        for (int d = 0; d < Dim; ++d) pairs.vector[e * Dim + d] = points[k][d] - xi[d];
      ++e;
    });
  });
  if (options.correct_moments && options.form == project::LaplacianForm::renormalised) {
    correct_moments_on_images(pairs, particles, images, points, entry_point, h);
    drop_own_images<Dim>(pairs, options);
  }
  return pairs;
}

template LaplacianPairs build_laplacian_pairs<2>(const ParticleSet<2>&, const Kernel&, const LaplacianOptions&);

}  // namespace frostwall::sph
