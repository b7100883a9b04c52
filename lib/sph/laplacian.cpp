#include "sph/laplacian.hpp"

#include <Eigen/Dense>
#include <deque>
#include <stdexcept>

#include "sph/cell_list.hpp"
#include "sph/moment_correction.hpp"
#include "sph/parallel.hpp"
#include "sph/symmetry_group.hpp"

namespace frostwall::sph {


template <int Dim>
MirrorImages<Dim> mirror_images(const ParticleSet<Dim>& particles, double reach, const std::vector<double>& own_reach) {
  MirrorImages<Dim> images;
  if (particles.mirrors.empty()) return images;
  const std::vector<Vec<Dim>> free_points(particles.position.begin(),
                                          particles.position.begin() + particles.n_free);
  const CellList<Dim> free_cells(free_points, reach);
  // The free particles lie on one side of each plane (the fundamental
  // domain); an image further than the reach beyond any plane is too far,
  // a test far cheaper than a cell query.
  std::vector<double> side(particles.mirrors.size(), 0.0);
  for (std::size_t p = 0; p < side.size(); ++p) {
    const auto& m = particles.mirrors[p];
    double sum = 0.0;
    for (const auto& x : free_points) sum += (x - m.point).dot(m.normal);
    side[p] = sum >= 0.0 ? 1.0 : -1.0;
  }
  auto beyond_reach = [&](const Vec<Dim>& y, double r) {
    for (std::size_t p = 0; p < side.size(); ++p) {
      const auto& m = particles.mirrors[p];
      if (-side[p] * (y - m.point).dot(m.normal) > r) return true;
    }
    return false;
  };
  double scale = particles.spacing;
  for (const auto& x : particles.position) scale = std::max(scale, x.norm());

  // Breadth-first over the group the planes generate; an element is kept
  // (and extended) only while it still puts some image within reach.
  std::vector<Vec<Dim>> image(particles.size());
  std::vector<char> wanted(particles.size());
  std::vector<Isometry<Dim>> seen{Isometry<Dim>{}};
  std::deque<Isometry<Dim>> queue{Isometry<Dim>{}};
  constexpr std::size_t max_elements = 4096;
  while (!queue.empty()) {
    const Isometry<Dim> g = queue.front();
    queue.pop_front();
    for (const auto& plane : particles.mirrors) {
      const Isometry<Dim> next = Isometry<Dim>::reflection(plane).after(g);
      bool known = false;
      for (const auto& s : seen) known = known || s.same_as(next, scale);
      if (known) continue;
      seen.push_back(next);
      if (seen.size() > max_elements)
        throw std::runtime_error("mirror planes generate too many images (planes not a finite symmetry?)");
      // Which particles' images under `next` are wanted (in parallel), then
      // those images in particle order.
      for_each_particle(particles.size(), [&](std::size_t j) {
        const Vec<Dim> y = next(particles.position[j]);
        image[j] = y;
        // A particle on a plane is its own image: nothing to add.
        wanted[j] = (y - particles.position[j]).norm() >= 1e-9 * particles.spacing &&
                    !beyond_reach(y, own_reach.empty() ? reach : std::min(reach, own_reach[j])) &&
                    free_cells.any_within(y, reach);
      });
      bool reaches = false;
      for (std::size_t j = 0; j < particles.size(); ++j) {
        if (!wanted[j]) continue;
        reaches = true;
        images.position.push_back(image[j]);
        images.source.push_back(static_cast<std::uint32_t>(j));
        images.linear.push_back(next.A);
      }
      if (reaches) queue.push_back(next);
    }
  }
  return images;
}

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
    if (lonely[i]) throw std::runtime_error("a particle has no neighbour within the kernel support (other than its own mirror images)");

  pairs.row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) pairs.row_start[i + 1] = pairs.row_start[i] + count[i];
  const std::size_t nnz = pairs.row_start[n];
  pairs.column.resize(nnz);
  pairs.weight.resize(nnz);
  if (options.keep_directions) pairs.direction2.resize(nnz * Dim);

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
      ++e;
    });
  });
  if (options.correct_moments && options.form == project::LaplacianForm::renormalised) {
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
    const auto report = correct_pair_moments<Dim>(pairs, particles.position, particles.volume, pair_vector, to_image, scale);
    pairs.moments_corrected = report.corrected;
    pairs.smallest_weight_factor = report.smallest_factor;
    pairs.largest_weight_factor = report.largest_factor;
    // Drop the own-image pairs (no flux).
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
        ++out;
      }
    }
    pairs.row_start[n] = out;
    pairs.column.resize(out);
    pairs.weight.resize(out);
    if (options.keep_directions) pairs.direction2.resize(out * Dim);
  }
  return pairs;
}

template <int Dim>
std::vector<Isometry<Dim>> symmetry_group(const std::vector<MirrorPlane<Dim>>& planes, double length_scale) {
  std::vector<Isometry<Dim>> group{Isometry<Dim>{}};
  for (std::size_t k = 0; k < group.size(); ++k)
    for (const auto& plane : planes) {
      const Isometry<Dim> next = Isometry<Dim>::reflection(plane).after(group[k]);
      bool known = false;
      for (const auto& g : group) known = known || g.same_as(next, length_scale);
      if (known) continue;
      if (group.size() >= 4096) throw std::runtime_error("mirror planes do not generate a finite symmetry group");
      group.push_back(next);
    }
  return group;
}

template std::vector<Isometry<2>> symmetry_group<2>(const std::vector<MirrorPlane<2>>&, double);
template MirrorImages<2> mirror_images<2>(const ParticleSet<2>&, double, const std::vector<double>&);
template LaplacianPairs build_laplacian_pairs<2>(const ParticleSet<2>&, const Kernel&,
                                                 const LaplacianOptions&);

}  // namespace frostwall::sph
