#include "freezing/sensor_points.hpp"

#include "particles/symmetry_group.hpp"

namespace frostwall::freezing {

std::vector<particles::Vec<2>> sensor_points(const project::Project& p, const Model& m) {
  std::vector<particles::Vec<2>> where;
  if (!m.shaft) {
    for (const auto& s : p.monitoring) where.emplace_back(s.x, s.y);
    return where;
  }
  const auto group = particles::symmetry_group(m.particles().mirrors, m.shaft->far_field_radius);
  for (const auto& s : p.monitoring) {
    particles::Vec<2> x(s.x, s.y), inside = x;
    for (const auto& g : group)
      if (geometry::inside_wedge(m.shaft->wedge, g(x))) {
        inside = g(x);
        break;
      }
    where.push_back(inside);
  }
  return where;
}

}  // namespace frostwall::freezing
