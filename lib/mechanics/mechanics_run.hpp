// The thermo-mechanical part of a plain-geometry run (project "mechanics"):
// the PD solid on the thermal model's free particles, brought to
// equilibrium by adaptive dynamic relaxation, staggered with the heat
// conduction. After each thermal step it re-equilibrates only when some
// particle's temperature has moved by relaxation.temperature_change (K)
// since the last equilibrium, and at every snapshot, warm-starting from
// the last displacement; bonds beyond their critical stretch break after
// each equilibrium, which is then sought again until none break.
// With pores, it re-equilibrates too when some pore particle's frozen
// fraction has moved by relaxation.frozen_fraction_change, and the
// freezing pores load the solid (pd/pore_expansion.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "pd/equilibrium.hpp"
#include "pd/pore_expansion.hpp"
#include "pd/solid.hpp"
#include "project/project.hpp"
#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"

namespace frostwall::mechanics {

using freezing::Model;

class MechanicsRun : public freezing::SolidView {
 public:
  // The model's thermal pairs are cut where bonds break when the project's
  // cracks insulate.
  MechanicsRun(const project::Project& p, Model& m);
  // force: equilibrate whatever the temperature change (snapshots).
  void update(const thermal::ThermalModel& model, double t, bool force);
  const pd::PdSolid& solid() const { return *solid_; }
  const std::vector<double>& displacement() const override { return u_; }  // 2 per free particle
  std::vector<double> damage() const override { return solid_->damage(); }
  std::vector<std::array<double, 3>> stress() const { return solid_->stress(u_, dT_); }  // Pa
  // Run facts for the summary: relaxations, iterations, broken bonds.
  nlohmann::json facts() const;
  // Called after every equilibrium (time, s): the damage record follows.
  std::function<void(double)> after_equilibrium;
  // The midpoints of the first bonds to break (between free particles),
  // and when (s): where damage started.
  const std::vector<pd::Vec2>& first_damage() const { return first_damage_; }
  double first_damage_time() const { return first_damage_time_; }
  // Time of the last equilibrium, s.
  double equilibrium_time() const { return t_equilibrium_; }

 private:
  const project::Mechanics& mechanics_;
  std::unique_ptr<pd::PdSolid> solid_;
  std::optional<pd::DirectEquilibrium> direct_;  // mechanics.equilibrium "direct"
  std::optional<pd::PoreExpansion> pores_;
  std::vector<double> f_equilibrium_;       // liquid fractions at the last equilibrium
  std::vector<double> frozen_equilibrium_;  // each pore's frozen fraction then
  double t_equilibrium_ = 0.0;
  std::vector<pd::Vec2> first_damage_;
  double first_damage_time_ = 0.0;
  thermal::ThermalModel* thermal_ = nullptr;
  std::vector<double> u_, dT_, T_equilibrium_;
  std::size_t relaxations_ = 0, iterations_ = 0, unconverged_ = 0, broken_ = 0, insulated_ = 0;
  int largest_ = 0;  // iterations of the longest relaxation
};

}  // namespace frostwall::mechanics
