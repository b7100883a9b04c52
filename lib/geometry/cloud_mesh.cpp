#include "geometry/cloud_mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "geometry/triangulation.hpp"

namespace frostwall::geometry {

std::vector<Triangle> cloud_triangles(const std::vector<particles::Vec<2>>& P, const std::vector<double>& max_edge_at) {
  if (P.size() > 0xffffffffu) throw std::invalid_argument("triangles: too many points");
  const bool one = max_edge_at.size() == 1;
  if (!one && max_edge_at.size() != P.size()) throw std::invalid_argument("triangles: one max_edge per point expected");
  for (double m : max_edge_at)
    if (!(m > 0.0)) throw std::invalid_argument("triangles: max_edge must be > 0");
  auto limit = [&](std::uint32_t i) { return one ? max_edge_at[0] : max_edge_at[i]; };
  for (const auto& x : P)
    if (!x.allFinite()) throw std::invalid_argument("triangles: non-finite point");
  std::vector<Triangle> triangles;
  for (const Triangle& v : delaunay_faces(P)) {
    double longest2 = 0.0;
    for (int k = 0; k < 3; ++k) longest2 = std::max(longest2, (P[v[k]] - P[v[(k + 1) % 3]]).squaredNorm());
    const double m = std::max({limit(v[0]), limit(v[1]), limit(v[2])});
    if (longest2 <= m * m) triangles.push_back(v);  // inf stays inf
  }
  return triangles;
}

}  // namespace frostwall::geometry
