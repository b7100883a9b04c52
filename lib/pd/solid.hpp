// The peridynamic solid of a plain geometry: its free particles (the
// thermal model's, same indices), the ghost points its supports add, and
// the bonds of every free particle to the points within the horizon
// (CSR, built once; broken bonds stay in the list with mu = 0).
//
// Supports are ghost points beyond the side, a horizon deep, apart from
// the thermal model's fixed layers (physics.md: each boundary's layers are
// excluded from the other physics' sums):
//  - roller: the side is a symmetry plane; ghosts are mirror images of the
//    particles (displacement reflected: u_ghost = A u_source), so the
//    normal displacement on the side is 0 and nothing else is constrained,
//    exactly, with no surface effect;
//  - fixed / prescribed displacement: reflections of the particles across
//    the side, held at 0 / the given displacement;
//  - free: no ghosts; the surface correction (Madenci & Oterkus) scales
//    each bond by the stiffness its ends lack: g_i^d = W_continuum / W_i
//    under a uniaxial strain along d, bond factor
//    [(n_x / gbar_x)^2 + (n_y / gbar_y)^2]^(-1/2), gbar the ends' mean.
// A ghost's temperature change is its source's.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "particles/vec.hpp"
#include "pd/bond_law.hpp"

namespace frostwall::pd {

using Vec2 = particles::Vec<2>;

struct SolidGeometry {
  std::vector<Vec2> position;  // free particles
  std::vector<double> volume;
  double spacing = 0.0;
  double width = 0.0, height = 0.0;  // the rectangle [0, width] x [0, height]
};

class PdSolid {
 public:
  PdSolid(const SolidGeometry& geometry, const project::Mechanics& mechanics, const BondLaw& law);
  bool linear() const { return linear_; }

  std::size_t size() const { return n_; }
  std::size_t bonds() const { return column_.size(); }
  const BondLaw& law() const { return law_; }
  const std::vector<Vec2>& position() const { return position_; }  // free particles, then ghosts

  // Force per unit volume on every free particle (2 values each) at the
  // displacement u (2 per free particle) and temperature change dT (K, per
  // free particle, from the stress-free reference).
  void forces(const std::vector<double>& u, const std::vector<double>& dT, std::vector<double>& force) const;
  // The same in the form the relaxation calls many times: u and dT given
  // at every point (ghosts included: extend() fills them), so the bond loop
  // is a plain gather; no allocation.
  void forces_extended(const std::vector<double>& u_all, const std::vector<double>& dT_all,
                       std::vector<double>& force) const;
  // Linear kinematics: the thermal part of the force, fixed while dT is,
  // -sum_j w s_T xi/|xi| (computed once per relaxation); then each
  // evaluation is force = thermal + sum_j (w / |xi|^3) (xi . (u_j - u_i)) xi.
  void thermal_force(const std::vector<double>& dT_all, std::vector<double>& force) const;
  void forces_linear(const std::vector<double>& u_all, const std::vector<double>& thermal,
                     std::vector<double>& force) const;
  std::size_t points() const { return position_.size(); }
  // u_all (2 per point) and dT_all (1 per point) from the free particles'.
  void extend(const std::vector<double>& u, std::vector<double>& u_all) const;
  // The same with held ghosts at 0: the displacement field's linear part
  // (what a stiffness times a direction needs).
  void extend_homogeneous(const std::vector<double>& u, std::vector<double>& u_all) const;
  void extend_temperature(const std::vector<double>& dT, std::vector<double>& dT_all) const;
  // Sum over i's bonds of c G V_j / |xi|: bounds the stiffness a particle
  // sees (the relaxation's fictitious density).
  const std::vector<double>& stiffness() const { return stiffness_; }
  // Breaks every intact bond whose mechanical stretch s - s_T exceeds the
  // critical stretch; returns how many broke (never mended).
  // newly_broken (optional): the free particles (i, j) of each bond that
  // broke between two of them (not to a ghost).
  std::size_t break_bonds(const std::vector<double>& u, const std::vector<double>& dT,
                          std::vector<std::pair<std::uint32_t, std::uint32_t>>* newly_broken = nullptr);
  // A pre-crack: breaks every bond whose reference segment crosses the
  // segment a-b; returns how many.
  std::size_t cut(const Vec2& a, const Vec2& b);
  // s - s_T of every bond that can break (intact, bonded, not held), -inf
  // for the others: where a load step will first break one (MechanicsRun).
  std::vector<double> breakable_stretches(const std::vector<double>& u, const std::vector<double>& dT) const;
  // The work it took to break the broken bonds (J per metre of depth):
  // each bond's energy at its critical stretch s0, 1/2 c s0^2 |xi| V_i V_j
  // per pair (its stiffness when it broke), pre-cracks included. A crack
  // that cuts every bond across a line of length L costs G0 L.
  double broken_bond_energy() const { return broken_energy_; }
  // The largest mechanical stretch s - s_T over the intact bonds.
  double largest_stretch(const std::vector<double>& u, const std::vector<double>& dT) const;
  // Share of broken bonds of each free particle, weighted by volume (bonds
  // to held particles left out).
  std::vector<double> damage() const;
  // The PD stress estimate of each free particle (sigma_xx, sigma_yy,
  // sigma_xy, Pa): half the sum over its bonds of the bond force per unit
  // volume times the bond vector, 1/2 sum w (s - s_T) e (x) xi. A uniform
  // strain gives the continuum's stress where the neighbourhood is whole.
  std::vector<std::array<double, 3>> stress(const std::vector<double>& u, const std::vector<double>& dT) const;
  // Strain energy density of each free particle, 1/4 sum c G (s - s_T)^2 |xi| V_j.
  std::vector<double> energy_density(const std::vector<double>& u, const std::vector<double>& dT) const;

  // ---- several materials (a porous plate) ----
  // A free strain of each free particle beyond the thermal one (ice that
  // grows as it freezes): a bond takes the mean of its ends', as it takes
  // their mean temperature change.
  void set_eigenstrain(const std::vector<double>& eigenstrain);
  // Each free particle's stiffness relative to the matrix's (1): a bond
  // is two springs in series, each end's half, so its micromodulus is the
  // matrix's times 2 r_i r_j / (r_i + r_j); 0 when either end is 0 (liquid
  // water carries no bonds). Broken bonds stay broken.
  void set_stiffness_ratio(const std::vector<double>& ratio);
  // Held particles take the displacement they are given (the relaxation
  // leaves them): a loading device, so their bonds never break.
  void set_held(std::vector<std::uint8_t> held) {
    held_ = std::move(held);
    ++stiffness_version_;
  }
  bool held(std::size_t i) const { return !held_.empty() && held_[i]; }
  // Held particles that move together, rigidly, under the sum of their
  // forces (the relaxation gives each group one degree of freedom per axis).
  void set_groups(std::vector<std::vector<std::size_t>> groups) {
    groups_ = std::move(groups);
    ++stiffness_version_;
  }
  // Changes whenever the stiffness does (a bond broke, a material's
  // stiffness changed, held particles or groups changed): a factor of K
  // made at the same version is K's exact factor.
  std::uint64_t stiffness_version() const { return stiffness_version_; }
  const std::vector<std::vector<std::size_t>>& groups() const { return groups_; }
  // Whether the relaxation moves free particle i: not held and bonded.
  bool moves(std::size_t i) const { return (held_.empty() || !held_[i]) && stiffness_[i] > 0.0; }
  // Intact bonds of each free particle (its own row), and in all.
  std::size_t intact_bonds() const;
  // Volume of each free particle (m^2 per metre of depth).
  const std::vector<double>& volume() const { return volume_; }
  // Calls f(i, j, A, k3, xi) for every bond of free particle i (k3 = 0
  // once broken or without stiffness), in the linear kinematics' terms:
  // the force density on i is k3 (xi . (u_k - u_i)) xi, with the far end's displacement u_k = A u_j
  // (j its free particle; A the identity for a free particle, a
  // reflection for a roller image) or, for a held ghost, j = -1 and u_k
  // held. What the direct equilibrium (pd/equilibrium) assembles.
  template <class F>
  void for_each_spring(F&& f) const {
    static const Eigen::Matrix2d identity = Eigen::Matrix2d::Identity();
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
        const std::uint32_t k = column_[e];
        const Vec2 xi(xi_[2 * e], xi_[2 * e + 1]);
        if (k < n_) f(i, static_cast<long>(k), identity, stiffness3_[e], xi);
        else if (ghosts_[k - n_].held) f(i, -1L, identity, stiffness3_[e], xi);
        else f(i, static_cast<long>(ghosts_[k - n_].source), ghosts_[k - n_].map, stiffness3_[e], xi);
      }
  }
  // Calls f(i, k, intact) for every bond of the free particles (k a point).
  template <class F>
  void for_each_bond(F&& f) const {
    for (std::size_t i = 0; i < n_; ++i)
      for (std::size_t e = start_[i]; e < start_[i + 1]; ++e)
        f(i, source(column_[e]), position_[column_[e]], intact_[e] != 0);
  }

 private:
  struct Ghost {
    std::uint32_t source = 0;  // the free particle it images or reflects
    Eigen::Matrix2d map = Eigen::Matrix2d::Identity();
    bool held = false;  // true: displacement `held_u`; false: map * u_source
    Vec2 held_u = Vec2::Zero();
  };
  Vec2 displacement(std::uint32_t k, const std::vector<double>& u) const;
  // s - s_T of bond e of particle i (the exact stretch).
  double mechanical_stretch(std::size_t i, std::size_t e, const std::vector<double>& u,
                            const std::vector<double>& dT) const {
    const std::uint32_t k = column_[e];
    const Vec2 ui(u[2 * i], u[2 * i + 1]);
    const double L = (position_[k] - position_[i] + displacement(k, u) - ui).norm();
    return (L - length_[e]) / length_[e] - thermal_stretch(i, k, dT);
  }
  std::uint32_t source(std::uint32_t k) const { return k < n_ ? k : ghosts_[k - n_].source; }
  // Particle i's share of bond e's energy at its critical stretch (the
  // row holds each pair twice; a ghost's row is not the body's).
  double break_energy(std::size_t i, std::size_t e) const {
    const double s0 = std::isfinite(law_.critical_stretch) ? law_.critical_stretch : 0.0;
    return 0.25 * weight_[e] * s0 * s0 * length_[e] * volume_[i];
  }
  double thermal_stretch(std::size_t i, std::uint32_t k, const std::vector<double>& dT) const {
    const std::uint32_t j = source(k);
    const double eigen = eigen_.empty() ? 0.0 : 0.5 * (eigen_[i] + eigen_[k]);
    return law_.thermal_stretch_per_K * 0.5 * (dT[i] + dT[j]) + eigen;
  }

  BondLaw law_;
  std::size_t n_ = 0;
  std::vector<Vec2> position_;
  std::vector<Ghost> ghosts_;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> column_;  // point index (>= n_: ghost)
  std::vector<double> length_;         // |xi|
  std::vector<double> weight_;         // c G V_j share (force per unit volume per unit stretch); 0 once broken
  std::vector<double> matrix_weight_;  // weight_ of the matrix material (set_stiffness_ratio scales it)
  std::vector<double> eigen_;          // per point (ghosts: their source's); empty: none
  std::vector<std::uint8_t> held_;     // per free particle; empty: none
  std::vector<std::vector<std::size_t>> groups_;
  std::vector<double> xi_;          // reference bond vector x_j - x_i, 2 per bond
  std::vector<double> stiffness3_;  // w / |xi|^3 (linear kinematics; 0 once broken)
  bool linear_ = true;
  std::vector<double> volume_share_;  // V_j share (damage)
  std::vector<double> volume_;        // free particles'
  mutable std::vector<std::uint8_t> intact_;
  std::vector<double> stiffness_;
  std::uint64_t stiffness_version_ = 0;
  double broken_energy_ = 0.0;  // J/m
};

}  // namespace frostwall::pd
