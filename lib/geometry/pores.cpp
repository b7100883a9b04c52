#include "geometry/pores.hpp"

#include <cmath>
#include <limits>

namespace frostwall::geometry {

std::vector<int> pore_membership(const std::vector<particles::Vec<2>>& position, std::size_t n,
                                 const std::vector<project::Pore>& pores) {
  std::vector<int> pore(n, -1);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t p = 0; p < pores.size(); ++p)
      if (std::hypot(position[i][0] - pores[p].x, position[i][1] - pores[p].y) < pores[p].radius) {
        pore[i] = static_cast<int>(p);
        break;
      }
  return pore;
}

std::vector<double> pore_frozen_fraction(const std::vector<int>& pore_of, std::size_t pores,
                                         const std::vector<double>& f, const std::vector<double>& volume) {
  std::vector<double> ice(pores, 0.0), all(pores, 0.0);
  for (std::size_t i = 0; i < pore_of.size(); ++i)
    if (const int p = pore_of[i]; p >= 0) {
      ice[p] += volume[i] * (1.0 - f[i]);
      all[p] += volume[i];
    }
  for (std::size_t p = 0; p < pores; ++p) ice[p] = all[p] > 0.0 ? ice[p] / all[p] : 0.0;
  return ice;
}

NearestRim nearest_rim(const particles::Vec<2>& x, const std::vector<project::Pore>& pores) {
  NearestRim nearest{std::numeric_limits<double>::infinity(), -1};
  for (std::size_t p = 0; p < pores.size(); ++p) {
    const double d = std::hypot(x[0] - pores[p].x, x[1] - pores[p].y) - pores[p].radius;
    if (d < nearest.distance) nearest = {d, static_cast<int>(p)};
  }
  return nearest;
}

}  // namespace frostwall::geometry
