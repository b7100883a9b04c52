// Brine pipes: the pipe wall's temperature and the heat the brine
// takes out of the ground, per metre of pipe, over the run. Recorded after
// every step from the film law Q = h P (T_wall - T_brine); the integral of
// that law over the run is reported beside the heat the integrator took out
// through the pipe walls, so the two can be compared (they are the same
// heat, counted from the film and from the ground). A pipe held at the heat
// it draws instead logs its wall's temperature at that heat (pipe_wall.csv,
// the summary's "pipe_wall").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "project/project.hpp"
#include "summary/summary.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::freezing {

class BrineLog {
 public:
  // boundary: the pipes' boundary id; sample_times (s): when a row is kept.
  BrineLog(const project::Pipe& pipe, const thermal::ThermalModel& model, std::size_t boundary,
           std::vector<double> sample_times);
  void after_step(const thermal::ThermalModel& model, double t);
  // The summary's block and the CSV file's stem: "brine", or "pipe_wall"
  // for pipes held at the heat they draw.
  const char* summary_key() const { return drawn_heat_ ? summary::keys::pipe_wall : summary::keys::brine; }
  // Writes <summary_key>.csv; returns the summary's block.
  nlohmann::json finish(const std::filesystem::path& out) const;

 private:
  struct Row {
    double day, brine, wall, heat_per_metre;  // degC, degC (mean over the pipes), W/m of pipe
  };
  Row row(const thermal::ThermalModel& model, double t, double& section_rate) const;

  project::Pipe pipe_;
  std::size_t boundary_;
  bool drawn_heat_;
  double h_;                       // the film coefficient, W/(m2 K), as last applied
  std::vector<double> perimeter_;  // per pipe, in the section
  std::vector<double> sample_times_;
  std::size_t next_ = 0;
  std::vector<Row> rows_;
  double t_last_ = 0.0, rate_last_ = 0.0, extracted_ = 0.0;  // J/m of the section, trapezoid over steps
};

}  // namespace frostwall::freezing
