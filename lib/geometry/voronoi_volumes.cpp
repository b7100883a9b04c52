#include "geometry/voronoi_volumes.hpp"

#include "particles/mirror_images.hpp"
#include "geometry/delaunay.hpp"

namespace frostwall::geometry {

namespace {
using K = geometry::Kernel2;
using Delaunay = geometry::IndexedDelaunay;
}  // namespace

void assign_voronoi_volumes(particles::ParticleSet<2>& particles, double reach) {
  const auto images = particles::mirror_images(particles, reach);
  constexpr std::size_t not_free = static_cast<std::size_t>(-1);
  std::vector<std::pair<K::Point_2, std::size_t>> points;
  points.reserve(particles.size() + images.position.size());
  for (std::size_t i = 0; i < particles.size(); ++i)
    points.emplace_back(K::Point_2(particles.position[i][0], particles.position[i][1]),
                        particles.is_free(i) ? i : not_free);
  for (const auto& y : images.position) points.emplace_back(K::Point_2(y[0], y[1]), not_free);
  const Delaunay dt(points.begin(), points.end());

  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    const std::size_t i = v->info();
    if (i == not_free) continue;
    // The cell's corners are the circumcentres of the incident triangles,
    // in counter-clockwise order; a cell touching the hull is unbounded.
    auto f = dt.incident_faces(v), done = f;
    std::vector<K::Point_2> corners;
    bool bounded = true;
    do {
      if (dt.is_infinite(f)) {
        bounded = false;
        break;
      }
      corners.push_back(dt.circumcenter(f));
    } while (++f != done);
    if (!bounded) continue;  // keeps its lattice volume
    double area = 0.0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const auto& a = corners[k];
      const auto& b = corners[(k + 1) % corners.size()];
      area += a.x() * b.y() - b.x() * a.y();
    }
    particles.volume[i] = 0.5 * area;
  }
}

}  // namespace frostwall::geometry
