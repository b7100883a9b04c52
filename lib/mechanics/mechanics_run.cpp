#include "mechanics/mechanics_run.hpp"

#include <algorithm>
#include <cmath>

#include "pd/relaxation.hpp"

namespace frostwall::mechanics {

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
  if (mechanics_.equilibrium == project::Mechanics::Equilibrium::direct) direct_.emplace();
  u_.assign(2 * P.n_free, 0.0);
  dT_.assign(P.n_free, 0.0);
  T_equilibrium_.assign(P.n_free, mechanics_.material.reference_temperature);
  if (!m.pore_of.empty() && mechanics_.freezing_expansion) {
    pores_.emplace(*mechanics_.freezing_expansion, mechanics_.material.elastic_modulus, rect.pores, m.pore_of);
    pores_->prepare(*solid_);
    const auto& model = *m.model;
    f_equilibrium_.assign(model.liquid_fraction().begin(), model.liquid_fraction().begin() + P.n_free);
    pores_->apply(*solid_, f_equilibrium_, model.volume());
    frozen_equilibrium_ = pores_->frozen_fraction(f_equilibrium_, model.volume());
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
    const auto now = pores_->frozen_fraction(f, model.volume());
    for (std::size_t p = 0; p < now.size(); ++p) froze = std::max(froze, std::abs(now[p] - frozen_equilibrium_[p]));
  }
  const bool freezing = froze >= mechanics_.frozen_fraction_change;
  if (!force && moved < threshold && !freezing) return;
  if (moved == 0.0 && froze == 0.0 && relaxations_ > 0) return;
  t_equilibrium_ = t;
  // The load at the last equilibrium (0) and now (1); in between it is
  // linear, and so, with linear kinematics and no bond breaking, is the
  // response.
  const std::vector<double> dT0 = dT_, f0 = f_equilibrium_, u0 = u_;
  std::vector<double> dT1(dT_.size()), f_load = f0;
  for (std::size_t i = 0; i < dT_.size(); ++i) {
    dT1[i] = T[i] - mechanics_.material.reference_temperature;
    T_equilibrium_[i] = T[i];
  }
  if (pores_) {
    f_equilibrium_.assign(f.begin(), f.begin() + dT_.size());
    frozen_equilibrium_ = pores_->frozen_fraction(f_equilibrium_, model.volume());
  }
  auto set_load = [&](double lambda) {
    for (std::size_t i = 0; i < dT_.size(); ++i) dT_[i] = dT0[i] + lambda * (dT1[i] - dT0[i]);
    if (!pores_) return;
    for (std::size_t i = 0; i < f_load.size(); ++i) f_load[i] = f0[i] + lambda * (f_equilibrium_[i] - f0[i]);
    pores_->apply(*solid_, f_load, model.volume());
    pores_->shape(*solid_, dT_, u_);
  };
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  auto adjust = [&] {
    ends.clear();
    const std::size_t broke = solid_->break_bonds(u_, dT_, &ends);
    if (thermal_) insulated_ += thermal_->cut_pairs(ends);
    if (first_damage_.empty() && !ends.empty()) {  // where damage starts
      first_damage_time_ = t;
      for (const auto& [i, j] : ends) first_damage_.push_back(0.5 * (solid_->position()[i] + solid_->position()[j]));
    }
    broken_ += broke;
    return broke > 0;
  };
  auto relax = [&](bool breaking) {
    const std::function<bool()> changes = breaking ? std::function<bool()>(adjust) : std::function<bool()>();
    const auto r =
        direct_ ? direct_->solve_adjusting(*solid_, u_, dT_, changes)
                : pd::relax_adjusting(*solid_, u_, dT_, mechanics_.tolerance, mechanics_.max_iterations, changes);
    ++relaxations_;
    iterations_ += r.iterations;
    largest_ = std::max(largest_, r.iterations);
    if (!r.converged) ++unconverged_;
  };
  const double critical = solid_->law().critical_stretch;
  if (!std::isfinite(critical) || relaxations_ == 0) {
    set_load(1.0);
    relax(true);
  } else {
    // Where the step first breaks a bond: the equilibrium at the full
    // load without breaking, then back along the line to the first bond's
    // critical stretch, so damage starts where it would under a slowly
    // growing load, not wherever one coarse step overshoots.
    const std::vector<double> s0 = solid_->breakable_stretches(u_, dT_);
    const std::vector<double> shape0 = pores_ ? pores_->shape_field() : std::vector<double>();
    set_load(1.0);
    relax(false);
    const std::vector<double> s1 = solid_->breakable_stretches(u_, dT_);
    double first = 1.0;
    bool breaks = false;
    for (std::size_t e = 0; e < s1.size(); ++e) {
      if (s1[e] <= critical) continue;
      breaks = true;
      if (std::isfinite(s0[e])) first = std::min(first, s0[e] >= critical ? 0.0 : (critical - s0[e]) / (s1[e] - s0[e]));
    }
    if (first < 1.0) {
      const double lambda = std::min(1.0, first * (1.0 + 1e-6) + 1e-9);
      for (std::size_t k = 0; k < u_.size(); ++k) u_[k] = u0[k] + lambda * (u_[k] - u0[k]);
      if (pores_) {
        std::vector<double> shape = pores_->shape_field();
        for (std::size_t k = 0; k < shape.size() && k < shape0.size(); ++k)
          shape[k] = shape0[k] + lambda * (shape[k] - shape0[k]);
        pores_->set_shape_field(std::move(shape));
      }
      set_load(lambda);
      relax(true);
      set_load(1.0);
    }
    // Nothing beyond critical at the full load: that equilibrium stands.
    if (breaks) relax(true);
  }
  if (after_equilibrium) after_equilibrium(t);
}

nlohmann::json MechanicsRun::facts() const {
  double largest_u = 0.0;
  for (std::size_t i = 0; 2 * i < u_.size(); ++i) largest_u = std::max(largest_u, std::hypot(u_[2 * i], u_[2 * i + 1]));
  const auto& law = solid_->law();
  pd::Vec2 onset = pd::Vec2::Zero();
  for (const auto& x : first_damage_) onset += x / double(first_damage_.size());
  return {{"bonds", solid_->bonds()},
          {"horizon", law.horizon},
          {"micromodulus", law.micromodulus},
          {"critical_stretch",
           std::isfinite(law.critical_stretch) ? nlohmann::json(law.critical_stretch) : nlohmann::json(nullptr)},
          {"equilibrium", direct_ ? "direct" : "dynamic_relaxation"},
          {"factorizations", direct_ ? direct_->factorizations() : 0},
          {"direct_solves", direct_ ? direct_->solves() : 0},
          {"relaxations", relaxations_},
          {"relaxation_iterations", iterations_},
          {"longest_relaxation", largest_},
          {"unconverged_relaxations", unconverged_},
          {"broken_bonds", broken_},
          {"first_damage", first_damage_.empty() ? nlohmann::json(nullptr)
                                                 : nlohmann::json{{"time", first_damage_time_},
                                                                  {"x", onset[0]},
                                                                  {"y", onset[1]},
                                                                  {"bonds", first_damage_.size()}}},
          {"thermal_pairs_cut", insulated_},
          {"largest_displacement", largest_u}};
}

}  // namespace frostwall::mechanics
