// A heat run, end to end: the model built from the project, the time loop,
// what is observed at every step and output time (closure, gaps under
// seepage, the wall, sensors, brine), the snapshot files and summary.json.
// The freezing engine runs it as it is; the mechanics engine runs the same
// loop with an extension (the PD solid and the pores' frost) that adds its
// own work at every step, its fields to the snapshots and its entries to
// the summary.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "freezing/model.hpp"
#include "freezing/thermometers.hpp"
#include "io/point_cloud_vtk.hpp"
#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"
#include "thermal/time_loop.hpp"

namespace frostwall::freezing {

// The displacement and damage of a solid on the model's free particles,
// for the plain results' sensors (mechanics/mechanics_run.hpp has one).
class SolidView {
 public:
  virtual ~SolidView() = default;
  virtual const std::vector<double>& displacement() const = 0;  // 2 per free particle, m
  virtual std::vector<double> damage() const = 0;               // per free particle
};

// What an engine built on the heat run adds to it. Each call comes at a
// fixed place in the loop: after_step after the run's own observers of the
// step (before the shaft's time samples); at_output before the plain
// results sample; add_fields after the thermal fields of a snapshot;
// summarise after the plain results' entries; run_facts last in "run".
class RunExtension {
 public:
  virtual ~RunExtension() = default;
  virtual void after_step(const thermal::ThermalModel&, double /*t*/) {}
  // After each step (and at t = 0), with the run's sensors updated: a shaft
  // section with `monitoring` only.
  virtual void read_sensors(const Thermometers&, double /*t*/) {}
  virtual void at_output(const thermal::ThermalModel&, double /*t*/, bool /*is_snapshot*/,
                         const std::filesystem::path& /*out*/, const std::string& /*stem*/) {}
  virtual void add_fields(io::PointCloudFrame&, const thermal::ThermalModel&) const {}
  virtual void summarise(nlohmann::ordered_json& /*summary*/, const std::filesystem::path& /*out*/) const {}
  virtual void run_facts(nlohmann::ordered_json& /*run*/) const {}
  virtual const SolidView* solid() const { return nullptr; }
  // Asked after every step: true ends the run there.
  virtual bool finished() const { return false; }
};

namespace detail {
class HeatRun;
}

// A heat run marched in parts: what run_heat does, with the time loop
// advanced to any stop in between (landing on it), so that runs coupled
// through what they exchange can march side by side. finish() once done
// writes the files and returns the summary.
class SteppedHeatRun {
 public:
  SteppedHeatRun(const project::Project& p, Model& built, const project::RunOptions& options,
                 RunExtension* extension = nullptr);
  ~SteppedHeatRun();
  double advance_to(double t);  // the time reached
  bool done() const;
  const thermal::TimeLoopResult& loop() const;  // the steps and boundary heat so far
  summary::Summary finish();

 private:
  std::unique_ptr<detail::HeatRun> run_;
  std::unique_ptr<thermal::TimeLoop> loop_;
};

// Runs the model to the project's end time and writes everything into
// project.output.directory (created if needed), the report excepted;
// returns the summary written.
// Throws project::ProjectError for input that cannot be run (before any
// output is written) and std::runtime_error for failures during the run.
summary::Summary run_heat(const project::Project& p, Model& built, const project::RunOptions& options,
                          RunExtension* extension = nullptr);

// What the run refuses before any work beyond the loader's checks (a
// regional flow without a far field, an output directory that cannot be
// made); throws project::ProjectError.
void check_run_inputs(const project::Project& p);
// The freezing engine: a shaft section or a plain geometry, SPH heat
// conduction with latent heat (and groundwater flow, brine pipes, the wall
// check when the project has them). Returns the summary written.
summary::Summary run(const project::Project& p, const project::RunOptions& options);

}  // namespace frostwall::freezing
