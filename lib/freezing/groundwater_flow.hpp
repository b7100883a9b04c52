// Groundwater flowing through a freezing shaft section: the
// steady Darcy flow on the run's own particle pairs and the heat it
// carries, either inside the conduction's backward-Euler step (coupled,
// the default) or alternated with the conduction (Strang: half the water's
// heat, the conduction integrator's step, the other half). The flow is
// solved again when the share of the water whose path ice has changed since
// the last solve exceeds groundwater.resolve_tolerance. Pipes carry no
// flow; the far field holds the regional potential -q . x, a rectangle's
// faces their heads. An Integrator
// itself, so the time loop, closure and energy balance see one step.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/point_cloud_vtk.hpp"
#include "groundwater/darcy_cloud.hpp"
#include "groundwater/permeability_law.hpp"
#include "post/frozen_area_trend.hpp"
#include "post/gap_closure.hpp"
#include "project/project.hpp"
#include "thermal/heat_advection.hpp"
#include "thermal/integrator.hpp"

namespace frostwall::freezing {

struct Model;

class GroundwaterFlow final : public thermal::Integrator {
 public:
  // Takes over the model's conduction integrator.
  // p.groundwater is set.
  GroundwaterFlow(const project::Project& p, Model& model);
  // The conduction's step, and no longer than the water takes to carry heat
  // across a particle (advective Courant number 1): the splitting's error
  // grows with the distance the heat front moves within one step.
  double preferred_step(const thermal::ThermalModel& model) const override;
  std::vector<double> advance(thermal::ThermalModel& model, double t, double dt) override;
  const char* name() const override { return name_.c_str(); }
  Integrator* wrapped() const override { return conduction_.get(); }

  int flow_solves() const { return solves_; }
  // The water entering through the boundaries at the last solve, m^2/s per
  // metre of depth (what leaves not counted).
  double inflow_from_boundary() const { return darcy_.inflow_from_boundary(true); }
  // Q_e of every pair at the last solve (groundwater::DarcyCloud).
  const std::vector<double>& pair_flux() const { return darcy_.pair_flux(); }
  // The VTU's flow fields at the last solve: "darcy_flux" (m/s, a vector;
  // 0 on fixed particles) and "relative_permeability".
  void add_fields(io::PointCloudFrame& frame, const thermal::ThermalModel& model) const;

 private:
  void solve_if_changed(const thermal::ThermalModel& model);
  const project::Groundwater& water_;
  groundwater::PermeabilityLaw law_;  // water_.law, evaluated
  std::unique_ptr<thermal::Integrator> conduction_;
  std::string name_;
  groundwater::DarcyCloud darcy_;
  thermal::HeatAdvection heat_;
  std::vector<double> k_, k_solved_, throughflow_;
  int solves_ = 0;
  // Steps of the limited scheme's stable step per splitting step (2: the
  // heat front crosses about one particle a step).
  double courant_ = 2.0;
};

// summary.json's "groundwater": the flow's inputs and solves, and closure
// per gap (days; null while open) with each gap's side of the shaft
// (upstream, downstream or flank: the gap's middle within 60 degrees of
// against, along, or across the flow) and the last gap to close; the
// verdict: closed (the day, the last gap and its side), or why not.
nlohmann::json groundwater_summary(const project::Groundwater& water, const GroundwaterFlow& flow,
                                   const post::GapClosure& gaps, const post::FrozenAreaTrend& frozen_area,
                                   std::optional<double> closure_time);

}  // namespace frostwall::freezing
