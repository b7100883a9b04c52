// Indexing of the fluid grid's cells and faces, shared by its .cpp files
// (internal to lib/pore_water).
#pragma once

#include <array>
#include <vector>

#include "pore_water/fluid_grid.hpp"

namespace frostwall::pore_water::grid {

using Cell = std::array<int, 3>;

// beta at |U_slip| -> 0: bed_gradient is linear in U there (its Darcy
// limit), so a tiny speed gives the limit without dividing by zero.
constexpr double tiny_speed = 1e-12;

inline Cell coords(const GridShape& s, int c) {
  return {c % s.cells[0], (c / s.cells[0]) % s.cells[1], c / (s.cells[0] * s.cells[1])};
}

inline int flat(const GridShape& s, const Cell& p) { return s.index(p[0], p[1], p[2]); }

// Faces normal to an axis are numbered like cells with one more along it;
// cell p's lower face has p's indices, its upper face one more on the axis.
inline int face_id(const GridShape& s, int axis, Cell q, int side = 0) {
  Cell d = s.cells;
  d[axis] += 1;
  q[axis] += side;
  return q[0] + d[0] * (q[1] + d[1] * q[2]);
}

// A face field averaged to the centre of cell c, per axis.
inline Vec3 face_mean(const GridShape& s, const std::array<std::vector<double>, 3>& field, int c) {
  const Cell p = coords(s, c);
  Vec3 mean;
  for (int a = 0; a < 3; ++a) mean[a] = 0.5 * (field[a][face_id(s, a, p)] + field[a][face_id(s, a, p, 1)]);
  return mean;
}

}  // namespace frostwall::pore_water::grid
