#include "pd/solid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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

PdSolid::PdSolid(const SolidGeometry& g, const project::Mechanics& m, const BondLaw& law)
    : law_(law), n_(g.position.size()), linear_(m.linear_kinematics), volume_(g.volume) {
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
  xi_.resize(2 * column_.size());
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      xi_[2 * e] = position_[column_[e]][0] - position_[i][0];
      xi_[2 * e + 1] = position_[column_[e]][1] - position_[i][1];
    }

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
  stiffness3_.resize(column_.size());
  for (std::size_t e = 0; e < column_.size(); ++e) stiffness3_[e] = weight_[e] / std::pow(length_[e], 3);
  matrix_weight_ = weight_;
}

void PdSolid::set_eigenstrain(const std::vector<double>& eigenstrain) {
  eigen_.resize(position_.size());
  for (std::size_t k = 0; k < position_.size(); ++k) eigen_[k] = eigenstrain[source(static_cast<std::uint32_t>(k))];
}

void PdSolid::set_stiffness_ratio(const std::vector<double>& ratio) {
  std::vector<std::uint8_t> changed(n_, 0);
  particles::for_each_particle(n_, [&](std::size_t i) {
    double sum = 0.0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const double ri = ratio[i], rj = ratio[source(column_[e])];
      const double series = ri + rj > 0.0 ? 2.0 * ri * rj / (ri + rj) : 0.0;
      const double w = intact_[e] ? matrix_weight_[e] * series : 0.0;
      changed[i] |= w != weight_[e];
      weight_[e] = w;
      stiffness3_[e] = weight_[e] / (length_[e] * length_[e] * length_[e]);
      sum += weight_[e] / length_[e];
    }
    stiffness_[i] = sum;
  });
  if (std::find(changed.begin(), changed.end(), 1) != changed.end()) ++stiffness_version_;
}

std::size_t PdSolid::intact_bonds() const {
  std::size_t count = 0;
  for (std::uint8_t b : intact_) count += b;
  return count;
}

Vec2 PdSolid::displacement(std::uint32_t k, const std::vector<double>& u) const {
  if (k < n_) return Vec2(u[2 * k], u[2 * k + 1]);
  const Ghost& g = ghosts_[k - n_];
  if (g.held) return g.held_u;
  return g.map * Vec2(u[2 * g.source], u[2 * g.source + 1]);
}

void PdSolid::extend(const std::vector<double>& u, std::vector<double>& u_all) const {
  u_all.resize(2 * position_.size());
  particles::for_each_particle(2 * n_, [&](std::size_t k) { u_all[k] = u[k]; });
  particles::for_each_particle(ghosts_.size(), [&](std::size_t g) {
    const Vec2 v = displacement(static_cast<std::uint32_t>(n_ + g), u);
    u_all[2 * (n_ + g)] = v[0];
    u_all[2 * (n_ + g) + 1] = v[1];
  });
}

void PdSolid::extend_homogeneous(const std::vector<double>& u, std::vector<double>& u_all) const {
  extend(u, u_all);
  for (std::size_t g = 0; g < ghosts_.size(); ++g)
    if (ghosts_[g].held) u_all[2 * (n_ + g)] = u_all[2 * (n_ + g) + 1] = 0.0;
}

void PdSolid::extend_temperature(const std::vector<double>& dT, std::vector<double>& dT_all) const {
  dT_all.resize(position_.size());
  for (std::size_t k = 0; k < position_.size(); ++k) dT_all[k] = dT[source(static_cast<std::uint32_t>(k))];
}

void PdSolid::forces(const std::vector<double>& u, const std::vector<double>& dT, std::vector<double>& force) const {
  std::vector<double> u_all, dT_all;
  extend(u, u_all);
  extend_temperature(dT, dT_all);
  forces_extended(u_all, dT_all, force);
}

void PdSolid::forces_extended(const std::vector<double>& u_all, const std::vector<double>& dT_all,
                              std::vector<double>& force) const {
  force.resize(2 * n_);
  const double* U = u_all.data();
  const double* D = dT_all.data();
  const double* X = xi_.data();
  const double* W = weight_.data();
  const double* Len = length_.data();
  const std::uint32_t* C = column_.data();
  const double half_kT = 0.5 * law_.thermal_stretch_per_K;
  const std::vector<double>& E = eigen_;
  auto half = [&](const std::vector<double>& v, std::uint32_t k) { return v.empty() ? 0.0 : 0.5 * v[k]; };
  particles::for_each_particle(n_, [&](std::size_t i) {
    const double uxi = U[2 * i], uyi = U[2 * i + 1], Di = D[i], Ei = half(E, static_cast<std::uint32_t>(i));
    double fx = 0.0, fy = 0.0;
    for (std::size_t e = start_[i], end = start_[i + 1]; e < end; ++e) {
      const std::uint32_t k = C[e];
      const double yx = X[2 * e] + U[2 * k] - uxi, yy = X[2 * e + 1] + U[2 * k + 1] - uyi;
      const double L = std::sqrt(yx * yx + yy * yy);
      // w (s - s_T) / L with s = L / |xi| - 1: the force along y.
      const double a = W[e] * ((L - Len[e]) / Len[e] - half_kT * (Di + D[k]) - Ei - half(E, k)) / L;
      fx += a * yx;
      fy += a * yy;
    }
    force[2 * i] = fx;
    force[2 * i + 1] = fy;
  });
}

void PdSolid::thermal_force(const std::vector<double>& dT_all, std::vector<double>& force) const {
  force.resize(2 * n_);
  const double half_kT = 0.5 * law_.thermal_stretch_per_K;
  const std::vector<double>& E = eigen_;
  particles::for_each_particle(n_, [&](std::size_t i) {
    double fx = 0.0, fy = 0.0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const double eigen = E.empty() ? 0.0 : 0.5 * (E[i] + E[column_[e]]);
      const double a = -weight_[e] * (half_kT * (dT_all[i] + dT_all[column_[e]]) + eigen) / length_[e];
      fx += a * xi_[2 * e];
      fy += a * xi_[2 * e + 1];
    }
    force[2 * i] = fx;
    force[2 * i + 1] = fy;
  });
}

void PdSolid::forces_linear(const std::vector<double>& u_all, const std::vector<double>& thermal,
                            std::vector<double>& force) const {
  force.resize(2 * n_);
  const double* U = u_all.data();
  const double* X = xi_.data();
  const double* K = stiffness3_.data();
  const std::uint32_t* C = column_.data();
  particles::for_each_particle(n_, [&](std::size_t i) {
    const double uxi = U[2 * i], uyi = U[2 * i + 1];
    // Two partial sums each: a single chain waits on every multiply-add.
    double fx0 = 0.0, fy0 = 0.0, fx1 = 0.0, fy1 = 0.0;
    std::size_t e = start_[i];
    const std::size_t end = start_[i + 1];
    for (; e + 2 <= end; e += 2) {
      const std::uint32_t k0 = C[e], k1 = C[e + 1];
      const double a0 = K[e] * (X[2 * e] * (U[2 * k0] - uxi) + X[2 * e + 1] * (U[2 * k0 + 1] - uyi));
      const double a1 = K[e + 1] * (X[2 * e + 2] * (U[2 * k1] - uxi) + X[2 * e + 3] * (U[2 * k1 + 1] - uyi));
      fx0 += a0 * X[2 * e];
      fy0 += a0 * X[2 * e + 1];
      fx1 += a1 * X[2 * e + 2];
      fy1 += a1 * X[2 * e + 3];
    }
    for (; e < end; ++e) {
      const std::uint32_t k = C[e];
      const double a = K[e] * (X[2 * e] * (U[2 * k] - uxi) + X[2 * e + 1] * (U[2 * k + 1] - uyi));
      fx0 += a * X[2 * e];
      fy0 += a * X[2 * e + 1];
    }
    force[2 * i] = thermal[2 * i] + fx0 + fx1;
    force[2 * i + 1] = thermal[2 * i + 1] + fy0 + fy1;
  });
}

std::size_t PdSolid::break_bonds(const std::vector<double>& u, const std::vector<double>& dT,
                                 std::vector<std::pair<std::uint32_t, std::uint32_t>>* newly_broken) {
  if (!std::isfinite(law_.critical_stretch)) return 0;
  // Rows in parallel (each touches only its own bonds), then the ends in
  // row order, so the list does not depend on the threads.
  std::vector<std::uint32_t> row_broken(n_, 0);
  std::vector<double> row_energy(n_, 0.0);
  particles::for_each_particle(n_, [&](std::size_t i) {
    if (held(i)) return;
    std::uint32_t count = 0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e)
      // The mechanical stretch: free thermal expansion breaks nothing. A
      // bond without stiffness (to liquid water) or to a held particle
      // carries nothing to break.
      if (intact_[e] && weight_[e] != 0.0 && !held(source(column_[e])) &&
          mechanical_stretch(i, e, u, dT) > law_.critical_stretch) {
        intact_[e] = 2;  // broken now
        row_energy[i] += break_energy(i, e);
        weight_[e] = stiffness3_[e] = 0.0;  // the force loops need no test
        ++count;
      }
    if (count == 0) return;
    row_broken[i] = count;
    stiffness_[i] = 0.0;  // what the particle still feels
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) stiffness_[i] += weight_[e] / length_[e];
  });
  std::size_t broken = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    if (row_broken[i] == 0) continue;
    broken += row_broken[i];
    broken_energy_ += row_energy[i];
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e)
      if (intact_[e] == 2) {
        intact_[e] = 0;
        if (newly_broken && column_[e] < n_) newly_broken->emplace_back(static_cast<std::uint32_t>(i), column_[e]);
      }
  }
  if (broken) ++stiffness_version_;
  return broken;
}

std::size_t PdSolid::cut(const Vec2& a, const Vec2& b) {
  auto cross = [](const Vec2& p, const Vec2& q) { return p[0] * q[1] - p[1] * q[0]; };
  std::size_t broken = 0;
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const Vec2 p = position_[i], q = position_[column_[e]];
      // Proper intersection of the segments p-q and a-b.
      const double d1 = cross(b - a, p - a), d2 = cross(b - a, q - a), d3 = cross(q - p, a - p),
                   d4 = cross(q - p, b - p);
      if (d1 * d2 < 0.0 && d3 * d4 < 0.0 && intact_[e]) {
        intact_[e] = 0;
        broken_energy_ += break_energy(i, e);
        weight_[e] = stiffness3_[e] = 0.0;
        ++broken;
      }
    }
  if (broken) ++stiffness_version_;
  return broken;
}

std::vector<double> PdSolid::breakable_stretches(const std::vector<double>& u, const std::vector<double>& dT) const {
  std::vector<double> s(column_.size(), -std::numeric_limits<double>::infinity());
  particles::for_each_particle(n_, [&](std::size_t i) {
    if (held(i)) return;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e)
      if (intact_[e] && weight_[e] != 0.0 && !held(source(column_[e]))) s[e] = mechanical_stretch(i, e, u, dT);
  });
  return s;
}

double PdSolid::largest_stretch(const std::vector<double>& u, const std::vector<double>& dT) const {
  double largest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n_; ++i)
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e)
      if (intact_[e]) largest = std::max(largest, mechanical_stretch(i, e, u, dT));
  return largest;
}

std::vector<double> PdSolid::damage() const {
  std::vector<double> phi(n_, 0.0);
  // After every equilibrium (the damage record): rows in parallel.
  particles::for_each_particle(n_, [&](std::size_t i) {
    double all = 0.0, lost = 0.0;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (held(source(column_[e]))) continue;  // a loading device, not material
      all += volume_share_[e];
      if (!intact_[e]) lost += volume_share_[e];
    }
    phi[i] = all > 0.0 ? lost / all : 0.0;
  });
  return phi;
}

std::vector<std::array<double, 3>> PdSolid::stress(const std::vector<double>& u, const std::vector<double>& dT) const {
  std::vector<std::array<double, 3>> sigma(n_, {0.0, 0.0, 0.0});
  particles::for_each_particle(n_, [&](std::size_t i) {
    const Vec2 ui(u[2 * i], u[2 * i + 1]);
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!intact_[e]) continue;
      const std::uint32_t k = column_[e];
      const Vec2 xi = position_[k] - position_[i];
      const Vec2 y = xi + displacement(k, u) - ui;
      const double f = 0.5 * weight_[e] * mechanical_stretch(i, e, u, dT) / y.norm();  // along y, per unit |y|
      sigma[i][0] += f * y[0] * xi[0];
      sigma[i][1] += f * y[1] * xi[1];
      sigma[i][2] += f * 0.5 * (y[0] * xi[1] + y[1] * xi[0]);
    }
  });
  return sigma;
}

std::vector<double> PdSolid::energy_density(const std::vector<double>& u, const std::vector<double>& dT) const {
  std::vector<double> w(n_, 0.0);
  particles::for_each_particle(n_, [&](std::size_t i) {
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      if (!intact_[e]) continue;
      const double s = mechanical_stretch(i, e, u, dT);
      w[i] += 0.25 * weight_[e] * s * s * length_[e];
    }
  });
  return w;
}

}  // namespace frostwall::pd
