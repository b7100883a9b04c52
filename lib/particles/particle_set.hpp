// The particle cloud as geometry hands it to the solver: positions and
// volumes, which particles are free and which hold a boundary temperature,
// and the mirror planes that make adiabatic sides. Fields live elsewhere.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::particles {

// A plane (line in 2-D) through `point` with unit `normal`; reflecting a
// particle across it makes the plane adiabatic (a symmetry plane).
template <int Dim>
struct MirrorPlane {
  Vec<Dim> point;
  Vec<Dim> normal;
  Vec<Dim> reflect(const Vec<Dim>& x) const { return x - 2.0 * (x - point).dot(normal) * normal; }
  double distance(const Vec<Dim>& x) const { return std::abs((x - point).dot(normal)); }
};

// Free particles come first (indices [0, n_free)); the rest are fixed-
// temperature particles whose boundary id indexes the model's boundaries.
// A fixed particle beyond its wall also knows its reflection across the
// wall, the point inside the ground it mirrors (NaN for a particle on the
// wall itself): its temperature is the wall's, extended antisymmetrically,
// 2 T_wall - T(reflection), so the wall sits where the geometry puts it
// (holding the layers at T_wall moves it by a fraction of a spacing).
template <int Dim>
struct ParticleSet {
  std::vector<Vec<Dim>> position;
  std::vector<double> volume;
  std::vector<int> boundary;         // -1 for free particles
  std::vector<Vec<Dim>> reflection;  // fixed particles: see above; free: NaN
  std::size_t n_free = 0;
  std::vector<MirrorPlane<Dim>> mirrors;
  double spacing = 0.0;  // the lattice spacing the cloud was made with (graded: the finest)
  // Graded clouds: each particle's own spacing (the side of a square of its
  // volume, so a lattice particle would have the lattice spacing); empty
  // for a lattice, where every particle has `spacing`.
  std::vector<double> local_spacing;

  std::size_t size() const { return position.size(); }
  bool is_free(std::size_t i) const { return i < n_free; }
  bool graded() const { return !local_spacing.empty(); }
  double spacing_of(std::size_t i) const { return local_spacing.empty() ? spacing : local_spacing[i]; }
  double coarsest_spacing() const {
    double s = spacing;
    for (double v : local_spacing) s = std::max(s, v);
    return s;
  }

  static Vec<Dim> on_wall() { return Vec<Dim>::Constant(std::numeric_limits<double>::quiet_NaN()); }
  void add(const Vec<Dim>& x, double v, int boundary_id, const Vec<Dim>& reflected = on_wall()) {
    position.push_back(x);
    volume.push_back(v);
    boundary.push_back(boundary_id);
    reflection.push_back(reflected);
  }
  // Puts free particles first (stable), as the solver expects.
  void order_free_first();
};

template <int Dim>
void ParticleSet<Dim>::order_free_first() {
  std::vector<std::size_t> order;
  order.reserve(size());
  for (std::size_t i = 0; i < size(); ++i)
    if (boundary[i] < 0) order.push_back(i);
  n_free = order.size();
  for (std::size_t i = 0; i < size(); ++i)
    if (boundary[i] >= 0) order.push_back(i);
  ParticleSet sorted;
  sorted.mirrors = mirrors;
  sorted.spacing = spacing;
  sorted.n_free = n_free;
  for (std::size_t i : order) {
    sorted.add(position[i], volume[i], boundary[i], reflection[i]);
    if (graded()) sorted.local_spacing.push_back(local_spacing[i]);
  }
  *this = std::move(sorted);
}

}  // namespace frostwall::particles
