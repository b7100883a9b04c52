#include "report/flow_arrows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frostwall::report {

std::vector<Arrow> flow_arrows(const FieldSnapshot& field, const WedgeSymmetry& symmetry, const MapWindow& window,
                               double domain_radius, int per_side) {
  std::vector<Arrow> arrows;
  if (field.darcy_flux.size() != field.position.size() || symmetry.mirror_lines > 1 || per_side < 1) return arrows;
  const double step = window.size / per_side;
  const particles::Vec<2> line(std::cos(symmetry.start), std::sin(symmetry.start));
  double longest = 0.0;
  for (int a = 0; a < per_side; ++a)
    for (int b = 0; b < per_side; ++b) {
      const particles::Vec<2> x(window.x0 + (a + 0.5) * step, window.y0 + (b + 0.5) * step);
      if (domain_radius > 0.0 && x.norm() > domain_radius) continue;
      const particles::Vec<2> folded = symmetry.fold(x);
      std::size_t nearest = field.position.size();
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < field.position.size(); ++i) {
        if (field.boundary[i] >= 0) continue;
        const double d = (field.position[i] - folded).squaredNorm();
        if (d < best) best = d, nearest = i;
      }
      // No free particle near (inside a pipe, beyond the domain): no arrow.
      if (nearest == field.position.size() || best > step * step) continue;
      particles::Vec<2> q = field.darcy_flux[nearest];
      if ((folded - x).norm() > 1e-9 * window.size) q = 2.0 * q.dot(line) * line - q;  // mirrored back
      arrows.push_back({x[0], x[1], q[0], q[1]});
      longest = std::max(longest, q.norm());
    }
  if (longest <= 0.0) return {};
  for (auto& arrow : arrows) {  // centred on the grid point
    arrow.dx *= 0.9 * step / longest;
    arrow.dy *= 0.9 * step / longest;
    arrow.x -= 0.5 * arrow.dx;
    arrow.y -= 0.5 * arrow.dy;
  }
  return arrows;
}

}  // namespace frostwall::report
