// The results of a plain-geometry run (rectangles: the verification
// problems), gathered while it runs: sensor readings at every output time
// (monitoring.csv, the summary's "monitoring"), the frozen front along the
// project's lines (output.front_along) and the 0.5 liquid-fraction
// isoline at each snapshot (interface_XXXX.vtp), as shaft runs write them.
#pragma once

#include <array>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "freezing/thermometers.hpp"
#include "post/field_sampler.hpp"
#include "post/isoline.hpp"
#include "post/linear_probe.hpp"
#include "project/project.hpp"
#include "freezing/model.hpp"

namespace frostwall::freezing {

class SolidView;  // freezing/heat_run.hpp

class PlainResults {
 public:
  PlainResults(const project::Project& p, const Model& m);
  ~PlainResults();
  // Sensors then also read the displacement and damage of the solid.
  void attach(const SolidView* solid);

  // At every output time (the regular series and the snapshots).
  void sample(double t, const thermal::ThermalModel& model);
  // At each snapshot: front lines and the interface file (stem "field_0001").
  void snapshot(double t, const thermal::ThermalModel& model, const std::filesystem::path& out,
                const std::string& stem);
  // Summary entries ("monitoring", "front_along", "interface") and monitoring.csv.
  nlohmann::json finish(const std::filesystem::path& out) const;

 private:
  const project::Project& project_;
  const Model& model_;
  double unit_;  // seconds per unit of the project's time
  post::FieldSampler sampler_;
  std::unique_ptr<Thermometers> sensors_;  // read at the output times, on which the steps land
  const SolidView* mechanics_ = nullptr;
  std::unique_ptr<post::LinearProbe> solid_sensors_;
  std::vector<std::unique_ptr<post::PointProbe>> lines_;            // samples along each front line
  std::vector<double> times_;                                       // of the sensor rows, project unit
  std::vector<std::vector<double>> readings_;                       // per row, per sensor
  std::vector<std::vector<std::array<double, 3>>> solid_readings_;  // per row, per sensor: ux, uy, damage
  nlohmann::json front_along_ = nlohmann::json::array(), interface_ = nlohmann::json::array();
  std::vector<particles::Vec<2>> curve_points_;  // particles and their mirror images
  std::vector<std::uint32_t> curve_source_;
  std::unique_ptr<post::IsolineMesh> curve_mesh_;
};

// The distance from the first sample to where the values first cross 0.5
// (linear between samples), samples `step` apart; nullopt when they never do.
std::optional<double> first_crossing(const std::vector<double>& values, double step);

}  // namespace frostwall::freezing
