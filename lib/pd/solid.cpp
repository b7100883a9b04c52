#include "pd/solid.hpp"

#include <algorithm>
#include <cmath>

#include "particles/cell_list.hpp"
#include "particles/mirror_images.hpp"
#include "particles/parallel.hpp"

namespace frostwall::pd {

namespace {

struct Side {
  const project::Support* support;
  Vec2 point, normal;  // normal points out of the rectangle
};

}  // namespace

PdSolid::PdSolid(const SolidGeometry& g, const project::Mechanics& m, const BondLaw& law) : law_(law), n_(g.position.size()) {
  const double delta = law.horizon, dx = g.spacing, reach = delta + 0.5 * dx;
  const std::array<Side, 4> sides{{{&m.left, Vec2(0, 0), Vec2(-1, 0)},
                                   {&m.right, Vec2(g.width, 0), Vec2(1, 0)},
                                   {&m.bottom, Vec2(0, 0), Vec2(0, -1)},
                                   {&m.top, Vec2(0, g.height), Vec2(0, 1)}}};
  // Roller sides: mirror images through every composition of their planes.
  particles::ParticleSet<2> free;
  for (std::size_t i = 0; i < n_; ++i) free.add(g.position[i], g.volume[i], -1);
  free.n_free = n_;
  free.spacing = dx;
  for (const auto& s : sides)
    if (s.support->kind == project::Support::Kind::roller) free.mirrors.push_back({s.point, s.normal});
  position_ = g.position;
  std::vector<double> volume = g.volume;
  if (!free.mirrors.empty()) {
    const auto images = particles::mirror_images(free, reach);
    for (std::size_t k = 0; k < images.position.size(); ++k) {
      position_.push_back(images.position[k]);
      ghosts_.push_back({images.source[k], images.linear[k], false, Vec2::Zero()});
      volume.push_back(g.volume[images.source[k]]);
    }
  }
  // Held sides: reflections of the particles (and roller images) within
  // reach of the side, held at the side's displacement.
  const std::size_t before_held = position_.size();
  for (const auto& s : sides) {
    const auto kind = s.support->kind;
    if (kind != project::Support::Kind::fixed && kind != project::Support::Kind::displacement) continue;
    const Vec2 held(s.support->ux, s.support->uy);
    for (std::size_t k = 0; k < before_held; ++k) {
      const double inside = -(position_[k] - s.point).dot(s.normal);  // depth below the side
      if (inside < 0.0 || inside > reach) continue;
      position_.push_back(position_[k] + 2.0 * inside * s.normal);
      ghosts_.push_back({source(static_cast<std::uint32_t>(k)), Eigen::Matrix2d::Identity(), true, held});
      volume.push_back(volume[k]);
    }
  }

  // Bonds within the horizon (partial volumes, as the thermal bonds).
  const particles::CellList<2> cells(position_, reach);
  std::vector<std::vector<std::pair<std::uint32_t, double>>> near(n_);  // (point, V_j share)
  particles::for_each_particle(n_, [&](std::size_t i) {
    cells.for_each_within(position_[i], reach, [&](std::uint32_t k, double r) {
      if (r == 0.0) return;
      const double share = std::clamp((delta + 0.5 * dx - r) / dx, 0.0, 1.0);
      if (share > 0.0) near[i].emplace_back(k, volume[k] * share);
    });
  });
  start_.assign(n_ + 1, 0);
  for (std::size_t i = 0; i < n_; ++i) start_[i + 1] = start_[i] + near[i].size();
  column_.resize(start_[n_]);
  length_.resize(start_[n_]);
  volume_share_.resize(start_[n_]);
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t b = 0; b < near[i].size(); ++b) {
      const std::size_t e = start_[i] + b;
      column_[e] = near[i][b].first;
      length_[e] = (position_[column_[e]] - position_[i]).norm();
      volume_share_[e] = near[i][b].second;
    }
  intact_.assign(column_.size(), 1);

  // Surface correction: each particle's energy under a uniaxial strain
  // along x and along y (ghosts following the same field), against the
  // continuum's.
  const double eps = 1e-3, W = law.uniaxial_energy(eps);
  std::vector<double> gx(n_), gy(n_);
  particles::for_each_particle(n_, [&](std::size_t i) {
    double wx = 0.0, wy = 0.0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const Vec2 xi = position_[column_[e]] - position_[i];
      for (int d = 0; d < 2; ++d) {
        Vec2 y = xi;
        y[d] *= 1.0 + eps;
        const double s = (y.norm() - length_[e]) / length_[e];
        (d == 0 ? wx : wy) += 0.25 * law.micromodulus * s * s * length_[e] * volume_share_[e];
      }
    }
    gx[i] = W / wx;
    gy[i] = W / wy;
  });
  weight_.resize(column_.size());
  stiffness_.assign(n_, 0.0);
  particles::for_each_particle(n_, [&](std::size_t i) {
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const std::uint32_t j = source(column_[e]);
      const Vec2 n = (position_[column_[e]] - position_[i]) / length_[e];
      const double bx = 0.5 * (gx[i] + gx[j]), by = 0.5 * (gy[i] + gy[j]);
      const double G = 1.0 / std::sqrt((n[0] / bx) * (n[0] / bx) + (n[1] / by) * (n[1] / by));
      weight_[e] = law.micromodulus * G * volume_share_[e];
      stiffness_[i] += weight_[e] / length_[e];
    }
  });
}

Vec2 PdSolid::displacement(std::uint32_t k, const std::vector<double>& u) const {
  if (k < n_) return Vec2(u[2 * k], u[2 * k + 1]);
  const Ghost& g = ghosts_[k - n_];
  if (g.held) return g.held_u;
  return g.map * Vec2(u[2 * g.source], u[2 * g.source + 1]);
}

void PdSolid::forces(const std::vector<double>& u, const std::vector<double>& dT, std::vector<double>& force) const {
  force.resize(2 * n_);
  particles::for_each_particle(n_, [&](std::size_t i) {
    const Vec2 ui(u[2 * i], u[2 * i + 1]);
    Vec2 f = Vec2::Zero();
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!intact_[e]) continue;
      const std::uint32_t k = column_[e];
      const Vec2 y = position_[k] - position_[i] + displacement(k, u) - ui;
      const double L = y.norm();
      const double s = (L - length_[e]) / length_[e];
      f += weight_[e] * (s - thermal_stretch(i, k, dT)) / L * y;
    }
    force[2 * i] = f[0];
    force[2 * i + 1] = f[1];
  });
}

std::size_t PdSolid::break_bonds(const std::vector<double>& u, const std::vector<double>& dT) {
  if (!std::isfinite(law_.critical_stretch)) return 0;
  std::size_t broken = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    const Vec2 ui(u[2 * i], u[2 * i + 1]);
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!intact_[e]) continue;
      const std::uint32_t k = column_[e];
      const double L = (position_[k] - position_[i] + displacement(k, u) - ui).norm();
      // The mechanical stretch: free thermal expansion breaks nothing.
      if ((L - length_[e]) / length_[e] - thermal_stretch(i, k, dT) > law_.critical_stretch) {
        intact_[e] = 0;
        ++broken;
      }
    }
  }
  return broken;
}

std::vector<double> PdSolid::damage() const {
  std::vector<double> phi(n_, 0.0);
  for (std::size_t i = 0; i < n_; ++i) {
    double all = 0.0, lost = 0.0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      all += volume_share_[e];
      if (!intact_[e]) lost += volume_share_[e];
    }
    phi[i] = all > 0.0 ? lost / all : 0.0;
  }
  return phi;
}

std::vector<double> PdSolid::energy_density(const std::vector<double>& u, const std::vector<double>& dT) const {
  std::vector<double> w(n_, 0.0);
  particles::for_each_particle(n_, [&](std::size_t i) {
    const Vec2 ui(u[2 * i], u[2 * i + 1]);
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!intact_[e]) continue;
      const std::uint32_t k = column_[e];
      const double L = (position_[k] - position_[i] + displacement(k, u) - ui).norm();
      const double s = (L - length_[e]) / length_[e] - thermal_stretch(i, k, dT);
      w[i] += 0.25 * weight_[e] * s * s * length_[e];
    }
  });
  return w;
}

}  // namespace frostwall::pd
