#include "freezing/groundwater_flow.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <fmt/core.h>

#include "groundwater/darcy_velocity.hpp"
#include "post/flow_side.hpp"
#include "project/units.hpp"
#include "freezing/model.hpp"
#include "summary/summary.hpp"
#include "thermal/backward_euler.hpp"

namespace frostwall::freezing {

using project::seconds_per_day;

namespace {

// The potential each fixed particle holds: on a shaft section -q . x on the
// far field, none (no flow) on the pipes; on a rectangle K h on a face with
// a head, continued beyond it along the straight head between it and the
// opposite face when that has a head too (exact for the flow before any
// ice), none on faces without one.
std::vector<double> fixed_potentials(const project::Project& p, const Model& m) {
  const auto& water = *p.groundwater;
  const auto& P = m.particles();
  std::vector<double> fixed;
  const auto* rect = std::get_if<project::Rectangle>(&p.geometry);
  const double K = water.conductivity_m_per_s();
  for (std::size_t j = P.n_free; j < P.size(); ++j) {
    const auto& x = P.position[j];
    if (!rect) {
      fixed.push_back(P.boundary[j] == m.shaft->far_field_boundary
                          ? -(water.darcy_flux[0] * x[0] + water.darcy_flux[1] * x[1])
                          : std::nan(""));
      continue;
    }
    const std::string& side = m.scene->boundaries[P.boundary[j]].name;
    const int s = side == "left" ? 0 : side == "right" ? 1 : side == "bottom" ? 2 : 3;
    const auto& head = rect->heads[s];
    const auto& opposite = rect->heads[s ^ 1];
    if (!head) fixed.push_back(std::nan(""));
    else if (!opposite) fixed.push_back(K * *head);
    else {
      const double length = s < 2 ? rect->width : rect->height, along = s < 2 ? x[0] : x[1];
      const double low = s % 2 == 0 ? *head : *opposite, high = s % 2 == 0 ? *opposite : *head;
      fixed.push_back(K * (low + (high - low) * along / length));
    }
  }
  return fixed;
}

thermal::AdvectionScheme scheme_of(project::Advection a) {
  switch (a) {
    case project::Advection::limited: return thermal::AdvectionScheme::limited;
    case project::Advection::upwind: return thermal::AdvectionScheme::upwind;
    case project::Advection::implicit: return thermal::AdvectionScheme::implicit;
    case project::Advection::coupled: return thermal::AdvectionScheme::coupled;
    default: return thermal::AdvectionScheme::limited;
  }
}

}  // namespace

GroundwaterFlow::GroundwaterFlow(const project::Project& p, Model& m)
    : water_(*p.groundwater),
      law_(groundwater::permeability_law(water_.law)),
      conduction_(std::move(m.integrator)),
      name_(std::string(conduction_->name()) + "+groundwater"),
      darcy_(m.model->pairs(), m.particles().volume, fixed_potentials(p, m)),
      heat_(water_.water_density * water_.water_heat_capacity, {}, scheme_of(water_.advection)),
      k_(m.particles().size(), 1.0) {
  if (water_.flows_coupled()) {
    auto* implicit = thermal::find_integrator<thermal::BackwardEuler>(conduction_.get());
    if (!implicit) throw std::logic_error("GroundwaterFlow: the coupled scheme needs the backward-Euler integrator");
    implicit->couple(&heat_);
    implicit->on_settled([this](const thermal::ThermalModel& model) { solve_if_changed(model); });
  }
  solve_if_changed(*m.model);
}

void GroundwaterFlow::solve_if_changed(const thermal::ThermalModel& model) {
  if (!water_.flows() && solves_ > 0) return;  // still water: the potential stays 0
  const auto& f = model.liquid_fraction();
  for (std::size_t i = 0; i < model.free_count(); ++i) k_[i] = law_.relative(f[i]);
  if (!k_solved_.empty()) {
    // The share of the water whose path has changed: each particle's
    // throughflow weighted by its permeability's relative change (at most
    // 1) since the last solve. Ice closing a gap changes few particles but
    // those that carry the water; a particle frozen off long ago none.
    // A particle that thaws carries what its new permeability lets
    // through, at most the mean particle's share.
    double changed = 0.0, total = 0.0;
    for (std::size_t i = 0; i < model.free_count(); ++i) total += throughflow_[i];
    const double mean = total / static_cast<double>(model.free_count());
    for (std::size_t i = 0; i < model.free_count(); ++i) {
      if (k_[i] == k_solved_[i]) continue;
      const double ratio = k_[i] / k_solved_[i];
      const double carried = ratio > 1.0 ? std::min(mean, throughflow_[i] * ratio) : throughflow_[i];
      changed += std::max(carried, throughflow_[i]) * std::min(1.0, std::abs(ratio - 1.0));
    }
    if (changed <= water_.resolve_tolerance * total) return;
  }
  darcy_.solve(k_);
  heat_.set_pair_flux(darcy_.pair_flux());
  k_solved_ = k_;
  const auto& P = model.pairs();
  const auto& Q = darcy_.pair_flux();
  throughflow_.assign(model.free_count(), 0.0);
  for (std::size_t i = 0; i < model.free_count(); ++i)
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) throughflow_[i] += 0.5 * std::abs(Q[e]);
  ++solves_;
}

double GroundwaterFlow::preferred_step(const thermal::ThermalModel& model) const {
  const double conduction = conduction_->preferred_step(model);
  if (!water_.flows()) return conduction;
  return std::min(conduction, courant_ * heat_.stable_step(model));  // unbounded when implicit
}

std::vector<double> GroundwaterFlow::advance(thermal::ThermalModel& model, double t, double dt) {
  if (!water_.flows()) return conduction_->advance(model, t, dt);  // still water carries nothing
  solve_if_changed(model);
  if (heat_.scheme() == thermal::AdvectionScheme::coupled)
    return conduction_->advance(model, t, dt);  // both in one step
  auto heat = heat_.advance(model, t, 0.5 * dt);
  const auto conducted = conduction_->advance(model, t, dt);
  const auto carried = heat_.advance(model, t + 0.5 * dt, 0.5 * dt);
  for (std::size_t b = 0; b < heat.size(); ++b) heat[b] += conducted[b] + carried[b];
  return heat;
}

void GroundwaterFlow::add_fields(io::PointCloudFrame& frame, const thermal::ThermalModel& model) const {
  const std::size_t n = frame.points.size();
  std::vector<double> flux(3 * n, 0.0), k(n, 1.0);
  if (!darcy_.potential().empty()) {
    const auto q = groundwater::darcy_flux_at_particles(model.pairs(), darcy_.potential(), k_solved_);
    for (std::size_t i = 0; i < q.size(); ++i) flux[3 * i] = q[i][0], flux[3 * i + 1] = q[i][1];
    for (std::size_t i = 0; i < std::min(n, k_solved_.size()); ++i) k[i] = k_solved_[i];
  }
  frame.vectors.emplace_back("darcy_flux", std::move(flux));
  frame.fields.emplace_back("relative_permeability", std::move(k));
}

namespace {

const char* side_of(const particles::Vec<2>& middle, const std::array<double, 2>& q) {
  return post::name(post::flow_side(middle, q));
}

nlohmann::json gap_json(const post::Gap& gap, const std::array<double, 2>& q) {
  nlohmann::json days = nlohmann::json::array(), flow = nlohmann::json::array();
  for (const auto& [t, through] : gap.flow)
    days.push_back(t / seconds_per_day), flow.push_back(through * seconds_per_day);
  return {{"between", gap.between},
          {summary::keys::closure_day,
           gap.closed ? nlohmann::json(*gap.closed / seconds_per_day) : nlohmann::json(nullptr)},
          {"bridge_closure_day",
           gap.bridge_closed ? nlohmann::json(*gap.bridge_closed / seconds_per_day) : nlohmann::json(nullptr)},
          {"position", side_of(gap.middle, q)},
          {"middle", {gap.middle[0], gap.middle[1]}},
          {"flow", {{"days", days}, {"m3_per_day_per_m", flow}}}};
}

}  // namespace

nlohmann::json groundwater_summary(const project::Groundwater& g, const GroundwaterFlow& flow,
                                   const post::GapClosure& gaps, const post::FrozenAreaTrend& frozen_area,
                                   std::optional<double> closure_time) {
  nlohmann::json s = {
      {"darcy_flux_m_per_day", {g.darcy_flux[0] * seconds_per_day, g.darcy_flux[1] * seconds_per_day}},
      {"hydraulic_gradient", g.hydraulic_gradient ? nlohmann::json(*g.hydraulic_gradient) : nlohmann::json(nullptr)},
      {"permeability_m2", g.permeability_m2()},
      {"permeability_law", groundwater::permeability_law(g.law).name()},
      {"impedance", g.law.model == groundwater::PermeabilityModel::impedance ? nlohmann::json(g.law.impedance)
                                                                             : nlohmann::json(nullptr)},
      {"floor", g.law.floor},
      {"flow_solves", flow.flow_solves()}};
  s[summary::keys::gaps] = nlohmann::json::array();
  for (const auto& gap : gaps.gaps()) s[summary::keys::gaps].push_back(gap_json(gap, g.darcy_flux));
  const post::Gap* last = gaps.last();
  s["last_gap"] = last ? gap_json(*last, g.darcy_flux) : nlohmann::json(nullptr);
  if (!closure_time) s[summary::keys::verdict] = frozen_area.no_closure_verdict();
  else if (last && last->closed)
    s[summary::keys::verdict] = fmt::format("closed on day {:.1f}; the last gap, {} ({}), on day {:.1f}",
                                            *closure_time / seconds_per_day, last->between,
                                            side_of(last->middle, g.darcy_flux), *last->closed / seconds_per_day);
  else s[summary::keys::verdict] = fmt::format("closed on day {:.1f}", *closure_time / seconds_per_day);
  s["frozen_area_growth_per_day"] = frozen_area.recent_growth_per_day();
  return s;
}

}  // namespace frostwall::freezing
