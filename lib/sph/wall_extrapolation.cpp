#include "sph/wall_extrapolation.hpp"

#include <Eigen/Dense>

#include "particles/mirror_images.hpp"
#include "particles/cell_list.hpp"
#include "sph/laplacian.hpp"

namespace frostwall::sph {

using particles::Vec;
using particles::ParticleSet;
using particles::CellList;
using particles::mirror_images;

template <int Dim>
WallExtrapolation build_wall_extrapolation(const ParticleSet<Dim>& particles, const Kernel& kernel,
                                           const SmoothingLengths& smoothing,
                                           const std::vector<bool>& insulated_walls) {
  // Graded clouds: each fixed particle's own support (its spacing is the
  // spacing of the ground it mirrors).
  const double reach = Kernel::support_factor * smoothing.largest();
  // Free particles and their mirror images (folded onto their sources).
  std::vector<Vec<Dim>> points(particles.position.begin(), particles.position.begin() + particles.n_free);
  std::vector<std::uint32_t> source(particles.n_free);
  for (std::size_t i = 0; i < particles.n_free; ++i) source[i] = static_cast<std::uint32_t>(i);
  const auto images = mirror_images(particles, 2.0 * reach);
  for (std::size_t k = 0; k < images.position.size(); ++k)
    if (images.source[k] < particles.n_free) {
      points.push_back(images.position[k]);
      source.push_back(images.source[k]);
    }
  const CellList<Dim> cells(points, Kernel::support_factor * smoothing.smallest());

  WallExtrapolation w;
  const std::size_t n_fixed = particles.size() - particles.n_free;
  w.row_start.assign(n_fixed + 1, 0);
  using P = Eigen::Matrix<double, Dim + 1, 1>;
  for (std::size_t f = 0; f < n_fixed; ++f) {
    const Vec<Dim>& x = particles.reflection[particles.n_free + f];
    const double h = smoothing.of(particles.n_free + f);
    w.row_start[f + 1] = w.row_start[f];
    if (x.hasNaN()) continue;
    const int b = particles.boundary[particles.n_free + f];
    const bool insulated = b >= 0 && static_cast<std::size_t>(b) < insulated_walls.size() && insulated_walls[b];
    const double sign = insulated ? -1.0 : 1.0;
    if (insulated) {
      std::int64_t at = -1;
      cells.for_each_within(x, 1e-6 * h, [&](std::uint32_t k, double) { at = source[k]; });
      if (at >= 0) {  // the reflection is a particle: its value exactly
        w.column.push_back(static_cast<std::uint32_t>(at));
        w.weight.push_back(-1.0);
        w.row_start[f + 1] = w.column.size();
        continue;
      }
    }
    std::vector<std::pair<std::uint32_t, double>> near;
    Eigen::Matrix<double, Dim + 1, Dim + 1> M = Eigen::Matrix<double, Dim + 1, Dim + 1>::Zero();
    auto basis = [&](const Vec<Dim>& y) {
      P p;
      p[0] = 1.0;
      p.template tail<Dim>() = (y - x) / h;  // scaled: M stays well conditioned
      return p;
    };
    cells.for_each_within(x, Kernel::support_factor * h, [&](std::uint32_t k, double r) {
      const double W = kernel.value(r, h);
      if (W <= 0.0) return;
      near.emplace_back(k, W);
      const P p = basis(points[k]);
      M += W * p * p.transpose();
    });
    if (near.empty()) continue;  // nothing to reflect: hold the wall value
    // Linear MLS where the neighbours span the plane, Shepard otherwise.
    const Eigen::FullPivLU<Eigen::Matrix<double, Dim + 1, Dim + 1>> lu(M);
    const bool linear = near.size() > static_cast<std::size_t>(Dim) + 1 && lu.rank() == Dim + 1 &&
                        std::abs(lu.determinant()) > 1e-10 * std::pow(M(0, 0), Dim + 1);
    double total = 0.0;
    for (const auto& [k, W] : near) total += W;
    const P e0 = linear ? P(lu.solve(P::UnitX())) : P::Zero();
    for (const auto& [k, W] : near) {
      w.column.push_back(source[k]);
      w.weight.push_back(sign * (linear ? W * e0.dot(basis(points[k])) : W / total));
    }
    w.row_start[f + 1] = w.column.size();
  }
  return w;
}

template WallExtrapolation build_wall_extrapolation<2>(const ParticleSet<2>&, const Kernel&, const SmoothingLengths&,
                                                       const std::vector<bool>&);

}  // namespace frostwall::sph
