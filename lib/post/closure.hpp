// Closure (the frozen columns of neighbouring pipes join): the unfrozen
// ground around the shaft axis is cut off from the far field by frozen
// ground. On a wedge this is a frozen path from one side to the other; on
// a full ring, a frozen wall around the shaft. Checked by a flood fill of
// unfrozen particles (liquid fraction > 0.5) from the far field over the
// lattice's 8-neighbourhood (links up to 1.5 spacings), so a frozen path
// one particle thick already closes.
#pragma once

#include <cstdint>
#include <vector>

#include "sph/vec.hpp"

namespace frostwall::post {

class ClosureDetector {
 public:
  ClosureDetector(const std::vector<sph::Vec<2>>& position, std::size_t n_free, double spacing,
                  double far_field_radius);
  bool closed(const std::vector<double>& liquid_fraction) const;

 private:
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> link_;
  std::vector<std::uint32_t> far_field_;  // seeds of the flood fill
  std::uint32_t axis_ = 0;               // the free particle nearest the shaft axis
};

}  // namespace frostwall::post
