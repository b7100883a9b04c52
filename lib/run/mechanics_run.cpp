#include "run/mechanics_run.hpp"

#include <algorithm>
#include <cmath>

#include "pd/relaxation.hpp"

namespace frostwall::run {

MechanicsRun::MechanicsRun(const project::Project& p, Model& m)
    : mechanics_(*p.mechanics), thermal_(mechanics_.cracks_insulate ? m.model.get() : nullptr) {
  const auto& rect = std::get<project::Rectangle>(p.geometry);
  const auto& P = m.particles();
  pd::SolidGeometry g;
  g.position.assign(P.position.begin(), P.position.begin() + P.n_free);
  g.volume.assign(P.volume.begin(), P.volume.begin() + P.n_free);
  g.spacing = P.spacing;
  g.width = rect.width;
  g.height = rect.height;
  solid_ = std::make_unique<pd::PdSolid>(g, mechanics_, pd::make_bond_law(mechanics_, p.numerics.horizon * P.spacing));
  u_.assign(2 * P.n_free, 0.0);
  dT_.assign(P.n_free, 0.0);
  T_equilibrium_.assign(P.n_free, mechanics_.material.reference_temperature);
  if (!m.pore_of.empty() && mechanics_.freezing_expansion) {
    pores_.emplace(*mechanics_.freezing_expansion, mechanics_.material.elastic_modulus, rect.pores, m.pore_of);
    pores_->prepare(*solid_);
    const auto& model = *m.model;
    f_equilibrium_.assign(model.liquid_fraction().begin(), model.liquid_fraction().begin() + P.n_free);
    pores_->apply(*solid_, f_equilibrium_, model.volume(), u_);
  }
}

void MechanicsRun::update(const thermal::ThermalModel& model, double t, bool force) {
  const auto& T = model.temperature();
  const auto& f = model.liquid_fraction();
  // How far any temperature moved since the last equilibrium, and the
  // largest change from the reference (the default threshold is 10 % of it).
  double moved = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < dT_.size(); ++i) {
    moved = std::max(moved, std::abs(T[i] - T_equilibrium_[i]));
    largest = std::max(largest, std::abs(T[i] - mechanics_.material.reference_temperature));
  }
  const double threshold = mechanics_.temperature_change.value_or(std::max(0.1 * largest, 1e-6));
  double froze = 0.0;  // how far any pore's frozen fraction moved
  if (pores_) {
    const auto now = pores_->frozen_fraction(f, model.volume()), then = pores_->frozen_fraction(f_equilibrium_, model.volume());
    for (std::size_t p = 0; p < now.size(); ++p) froze = std::max(froze, std::abs(now[p] - then[p]));
  }
  const bool freezing = froze >= mechanics_.frozen_fraction_change;
  if (!force && moved < threshold && !freezing) return;
  if (moved == 0.0 && froze == 0.0 && relaxations_ > 0) return;
  if (pores_) {
    f_equilibrium_.assign(f.begin(), f.begin() + dT_.size());
    pores_->apply(*solid_, f_equilibrium_, model.volume(), u_);
  }
  t_equilibrium_ = t;
  for (std::size_t i = 0; i < dT_.size(); ++i) {
    dT_[i] = T[i] - mechanics_.material.reference_temperature;
    T_equilibrium_[i] = T[i];
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  // Pores ride on their rings to within 1e-4 of the largest rim push.
  const double significant = 1e-4 * std::max(pores_ ? pores_->largest_push() : 0.0, 1e-12);
  auto adjust = [&] {
    ends.clear();
    const std::size_t broke = solid_->break_bonds(u_, dT_, thermal_ ? &ends : nullptr);
    if (thermal_) insulated_ += thermal_->cut_pairs(ends);
    broken_ += broke;
    const bool moved = pores_ && pores_->follow(*solid_, dT_, u_, significant);
    return broke > 0 || moved;
  };
  if (pores_) pores_->follow(*solid_, dT_, u_, significant);
  const auto r = pd::relax_adjusting(*solid_, u_, dT_, mechanics_.tolerance, mechanics_.max_iterations, adjust);
  ++relaxations_;
  iterations_ += r.iterations;
  largest_ = std::max(largest_, r.iterations);
  if (!r.converged) ++unconverged_;
  if (after_equilibrium) after_equilibrium(t);
}

nlohmann::json MechanicsRun::facts() const {
  double largest_u = 0.0;
  for (std::size_t i = 0; 2 * i < u_.size(); ++i) largest_u = std::max(largest_u, std::hypot(u_[2 * i], u_[2 * i + 1]));
  const auto& law = solid_->law();
  return {{"bonds", solid_->bonds()},
          {"horizon", law.horizon},
          {"micromodulus", law.micromodulus},
          {"critical_stretch", std::isfinite(law.critical_stretch) ? nlohmann::json(law.critical_stretch) : nlohmann::json(nullptr)},
          {"relaxations", relaxations_},
          {"relaxation_iterations", iterations_},
          {"longest_relaxation", largest_},
          {"unconverged_relaxations", unconverged_},
          {"broken_bonds", broken_},
          {"thermal_pairs_cut", insulated_},
          {"largest_displacement", largest_u}};
}

}  // namespace frostwall::run
