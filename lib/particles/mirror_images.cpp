#include "particles/mirror_images.hpp"

#include <Eigen/Dense>
#include <deque>
#include <stdexcept>

#include "particles/cell_list.hpp"
#include "particles/parallel.hpp"
#include "particles/symmetry_group.hpp"

namespace frostwall::particles {

template <int Dim>
MirrorImages<Dim> mirror_images(const ParticleSet<Dim>& particles, double reach, const std::vector<double>& own_reach) {
  MirrorImages<Dim> images;
  if (particles.mirrors.empty()) return images;
  const std::vector<Vec<Dim>> free_points(particles.position.begin(), particles.position.begin() + particles.n_free);
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

}  // namespace frostwall::particles
