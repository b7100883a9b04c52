// A square lattice of PD particles on [0, L]^2 (cell centres, spacing dx):
// the plates of the PD tests.
#pragma once

#include <cmath>

#include "pd/solid.hpp"

namespace frostwall::test {

inline pd::SolidGeometry square_lattice(double L, double dx) {
  pd::SolidGeometry g;
  const int n = static_cast<int>(std::lround(L / dx));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      g.position.emplace_back((i + 0.5) * dx, (j + 0.5) * dx);
      g.volume.push_back(dx * dx);
    }
  g.spacing = dx;
  g.width = g.height = L;
  return g;
}

}  // namespace frostwall::test
