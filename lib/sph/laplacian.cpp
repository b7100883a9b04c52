#include "sph/laplacian.hpp"

#include <Eigen/Dense>
#include <deque>
#include <stdexcept>

#include "sph/cell_list.hpp"
#include "sph/parallel.hpp"
#include "sph/symmetry_group.hpp"

namespace frostwall::sph {


template <int Dim>
MirrorImages<Dim> mirror_images(const ParticleSet<Dim>& particles, double reach) {
  MirrorImages<Dim> images;
  if (particles.mirrors.empty()) return images;
  const std::vector<Vec<Dim>> free_points(particles.position.begin(),
                                          particles.position.begin() + particles.n_free);
  const CellList<Dim> free_cells(free_points, reach);
  double scale = particles.spacing;
  for (const auto& x : particles.position) scale = std::max(scale, x.norm());

  // Breadth-first over the group the planes generate; an element is kept
  // (and extended) only while it still puts some image within reach.
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
      bool reaches = false;
      for (std::size_t j = 0; j < particles.size(); ++j) {
        const Vec<Dim> y = next(particles.position[j]);
        // A particle on a plane is its own image: nothing to add.
        if ((y - particles.position[j]).norm() < 1e-9 * particles.spacing) continue;
        bool near = false;
        free_cells.for_each_within(y, reach, [&](std::uint32_t, double) { near = true; });
        if (!near) continue;
        reaches = true;
        images.position.push_back(y);
        images.source.push_back(static_cast<std::uint32_t>(j));
      }
      if (reaches) queue.push_back(next);
    }
  }
  return images;
}

template <int Dim>
LaplacianPairs build_laplacian_pairs(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                     const LaplacianOptions& options) {
  const double h = options.h;
  const double reach = Kernel::support_factor * h;
  const double eta2 = 0.01 * h * h;  // eta = 0.1 h keeps F finite at tiny r

  // Every point a free particle can see: real particles, then mirror images.
  const MirrorImages<Dim> images = mirror_images(particles, reach);
  std::vector<Vec<Dim>> points = particles.position;
  std::vector<std::uint32_t> source(particles.size());
  for (std::size_t j = 0; j < particles.size(); ++j) source[j] = static_cast<std::uint32_t>(j);
  points.insert(points.end(), images.position.begin(), images.position.end());
  source.insert(source.end(), images.source.begin(), images.source.end());
  const CellList<Dim> cells(points, reach);

  LaplacianPairs pairs;
  pairs.dim = Dim;
  pairs.n_free = particles.n_free;
  const std::size_t n = particles.n_free;
  pairs.renormalisation.assign(n, 1.0);

  // First pass: neighbours per row (to size the CSR) and the moment sums.
  std::vector<std::size_t> count(n, 0);
  std::vector<char> lonely(n, 0);  // no neighbour at all: a geometry error
  for_each_particle(n, [&](std::size_t i) {
    double moment = 0.0;  // sum_j V_j F_ij |r_ij|^2, continuum value -Dim
    std::size_t c = 0;
    cells.for_each_within(particles.position[i], reach, [&](std::uint32_t k, double r) {
      if (r == 0.0) return;
      const std::uint32_t j = source[k];
      const double F = kernel.derivative(r, h) * r / (r * r + eta2);
      moment += particles.volume[j] * F * r * r;
      if (j != i) ++c;  // a particle's own image carries no flux (T_i - T_i)
    });
    count[i] = c;
    if (options.form == project::LaplacianForm::renormalised) {
      if (moment < 0.0) pairs.renormalisation[i] = -static_cast<double>(Dim) / moment;
      else lonely[i] = 1;
    }
  });
  for (std::size_t i = 0; i < n; ++i)
    if (lonely[i]) throw std::runtime_error("a particle has no neighbour within the kernel support");

  pairs.row_start.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) pairs.row_start[i + 1] = pairs.row_start[i] + count[i];
  const std::size_t nnz = pairs.row_start[n];
  pairs.column.resize(nnz);
  pairs.weight.resize(nnz);
  if (options.keep_directions) pairs.direction2.resize(nnz * Dim);

  // Second pass: the stored weights G_ij.
  for_each_particle(n, [&](std::size_t i) {
    std::size_t e = pairs.row_start[i];
    const Vec<Dim>& xi = particles.position[i];
    const double ci = pairs.renormalisation[i];
    cells.for_each_within(xi, reach, [&](std::uint32_t k, double r) {
      const std::uint32_t j = source[k];
      if (r == 0.0 || j == i) return;
      const double F = kernel.derivative(r, h) * r / (r * r + eta2);
      // A fixed particle has no equation of its own: its side uses c_i only.
      const double s = j < n ? 0.5 * (ci + pairs.renormalisation[j]) : ci;
      pairs.column[e] = j;
      pairs.weight[e] = -particles.volume[j] * F * s;
      if (options.keep_directions) {
        const Vec<Dim> rij = xi - points[k];
        for (int d = 0; d < Dim; ++d) pairs.direction2[e * Dim + d] = rij[d] * rij[d] / (r * r);
      }
      ++e;
    });
  });
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
template MirrorImages<2> mirror_images<2>(const ParticleSet<2>&, double);
template LaplacianPairs build_laplacian_pairs<2>(const ParticleSet<2>&, const Kernel&,
                                                 const LaplacianOptions&);

}  // namespace frostwall::sph
