// Free particles of a graded cloud. A centroidal Voronoi tessellation (CVT)
// with density s(x)^-4 has near-regular hexagonal cells whose size follows
// the size field s(x) (Gersho: cell size ~ density^(-1/(Dim+2))), so its
// generators are well-shaped, smoothly graded particles, and a particle's
// Voronoi cell (its volume) is centred on it, which keeps the kernel sums'
// first moments small.
//  - Seeds: CGAL's Delaunay mesher (Delaunay_mesher_2) meshes the region's
//    outline with the size field as its size criterion; each triangle asks
//    for area / s^2 particles (a particle of spacing s stands for s^2 of
//    ground), and the seeds go to triangle centroids so that every patch
//    of a few triangles gets its count.
//  - Lloyd iterations move every free particle to the density-weighted
//    centroid of its Voronoi cell, computed with the fixed particles (pipe
//    rings), the mirror images of everything (so cells end at mirror planes
//    and particles settle about half a spacing off them, as the lattice's
//    rows do) and reflections across the walls the cloud ends at (far-field
//    circle, rectangle faces; cells end there too).
#pragma once

#include <functional>
#include <vector>

#include "geometry/size_field.hpp"
#include "particles/particle_set.hpp"

namespace frostwall::geometry {

// A boundary the cloud ends at without particles on it: a line (radius 0:
// through `point` with unit `normal`) or a circle (centre `point`).
struct ReflectingWall {
  Vec2 point = Vec2::Zero();
  Vec2 normal = Vec2::UnitX();
  double radius = 0.0;
  double distance(const Vec2& x) const {
    return radius > 0.0 ? std::abs((x - point).norm() - radius) : std::abs((x - point).dot(normal));
  }
  // Across the wall at the same distance (radially for a circle).
  Vec2 reflect(const Vec2& x) const {
    if (radius > 0.0) {
      const double rho = (x - point).norm();
      return point + (2.0 * radius - rho) / rho * (x - point);
    }
    return x - 2.0 * (x - point).dot(normal) * normal;
  }
};

struct PlacementRegion {
  std::vector<Vec2> outline;                       // polygon around the region, counter-clockwise (seeding)
  std::function<bool(const Vec2&)> inside;         // where a free particle may sit
  std::vector<particles::MirrorPlane<2>> mirrors;  // adiabatic sides
  std::vector<Vec2> fixed;                         // fixed particles already placed (pipe rings)
  std::vector<ReflectingWall> walls;
};

struct PlacementReport {
  std::size_t particles = 0;
  int iterations = 0;
  double last_move = 0.0;  // largest move of the last iteration, in local spacings
};

// At most `iterations` Lloyd iterations; fewer once the cloud has settled
// (no particle moves more than 5 % of its spacing).
std::vector<Vec2> place_graded(const PlacementRegion& region, const SizeField& size, int iterations,
                               PlacementReport* report = nullptr);

// Each free particle's spacing: the size field, scaled so that the squares
// of the spacings add up to the free particles' volume (their Voronoi
// cells). The CVT keeps the seeds' count, which the same integral set, so
// the scale stays near 1. Sizes local_spacing to the set (fixed particles
// are left for the caller) and returns the scale.
double assign_free_spacing(particles::ParticleSet<2>& particles, const SizeField& size);

}  // namespace frostwall::geometry
