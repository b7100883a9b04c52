#include "porous_flow/darcy_velocity.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "particles/cell_list.hpp"
#include "particles/mirror_images.hpp"
#include "particles/parallel.hpp"

namespace frostwall::porous_flow {

using particles::Vec;

std::vector<Vec<2>> darcy_flux_at_particles(const particles::ParticleSet<2>& cloud, const std::vector<double>& potential,
                                            const std::vector<double>& k_r, double reach) {
  // Real particles and their mirror images (an image carries its source's
  // potential: the flow is symmetric about the planes kept for it).
  const auto images = particles::mirror_images(cloud, reach);
  std::vector<Vec<2>> point = cloud.position;
  std::vector<std::uint32_t> source(cloud.size());
  for (std::size_t i = 0; i < source.size(); ++i) source[i] = static_cast<std::uint32_t>(i);
  point.insert(point.end(), images.position.begin(), images.position.end());
  source.insert(source.end(), images.source.begin(), images.source.end());
  const particles::CellList<2> cells(point, reach);
  std::vector<Vec<2>> q(cloud.n_free, Vec<2>::Zero());
  particles::for_each_particle(cloud.n_free, [&](std::size_t i) {
    // Weights (1 - r/reach)^2 favour the nearest; the fit is exact for a
    // plane whatever they are.
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    Eigen::Vector2d b = Eigen::Vector2d::Zero();
    cells.for_each_within(cloud.position[i], reach, [&](std::uint32_t k, double r) {
      const double value = potential[source[k]];
      if (r == 0.0 || std::isnan(value)) return;
      const Eigen::Vector2d d = point[k] - cloud.position[i];
      const double w = (1.0 - r / reach) * (1.0 - r / reach);
      M += w * d * d.transpose();
      b += w * (value - potential[i]) * d;
    });
    if (std::abs(M.determinant()) > 1e-30 * M.squaredNorm()) q[i] = -k_r[i] * M.ldlt().solve(b);
  });
  return q;
}

}  // namespace frostwall::porous_flow
