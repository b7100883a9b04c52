// The mirror symmetry of a shaft run as summary.json records it ("wedge":
// M mirror lines, the wedge from start_deg over angle_deg). Folding maps
// any point of the section into the simulated wedge (where the field is);
// the copies map the wedge's front curves around the whole ring.
#pragma once

#include <vector>

#include "particles/vec.hpp"

namespace frostwall::report {

struct WedgeSymmetry {
  int mirror_lines = 0;  // M; 0 = no symmetry, the field covers the full circle
  double start = 0.0;    // rad, the wedge's first side (OA)
  double angle = 0.0;    // rad, pi / M

  // The point of the wedge with the same field value as x.
  particles::Vec<2> fold(const particles::Vec<2>& x) const;
  // The 2M elements of the dihedral group (rotations, then reflections), as
  // functions applied by `apply`; identity first. One element when M = 0.
  std::size_t copies() const { return mirror_lines > 0 ? 2 * static_cast<std::size_t>(mirror_lines) : 1; }
  particles::Vec<2> apply(std::size_t copy, const particles::Vec<2>& x) const;
};

}  // namespace frostwall::report
