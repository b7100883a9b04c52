#include "geometry/interface_planes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace frostwall::geometry {

InterfacePlanes interface_planes(const std::vector<geometry::Pipe2>& pipes) {
  InterfacePlanes p;
  const auto& first = pipes.front();
  p.OA = std::atan2(first.y, first.x);
  p.ring_radius = std::hypot(first.x, first.y);
  double gap = 2 * std::numbers::pi;  // to the next pipe of the same ring, CCW
  for (const auto& q : pipes) {
    if (&q == &first || q.ring != first.ring) continue;
    double a = std::atan2(q.y, q.x) - p.OA;
    while (a <= 1e-12) a += 2 * std::numbers::pi;
    gap = std::min(gap, a);
  }
  p.OB = p.OA + 0.5 * gap;
  std::map<int, std::pair<double, int>> rings;  // ring -> (sum of radii, pipes)
  for (const auto& q : pipes)
    if (q.ring >= 0) {
      rings[q.ring].first += std::hypot(q.x, q.y);
      ++rings[q.ring].second;
    }
  p.ring_radii.push_back(p.ring_radius);
  for (const auto& [ring, sum] : rings)
    if (ring != first.ring) p.ring_radii.push_back(sum.first / sum.second);
  std::sort(p.ring_radii.begin(), p.ring_radii.end());
  return p;
}

}  // namespace frostwall::geometry
