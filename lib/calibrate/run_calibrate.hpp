// `frostwall calibrate`: fits the ground's parameters to the thermometers'
// readings (calibrate.hpp gives what and within which bounds), then runs
// the project as calibrated and forecasts closure and the wall with a band.
//
// Into the project's output directory it writes what `frostwall run`
// writes for the calibrated project (its report written by the caller),
// with summary.json's "calibration" block (the fitted values and their 95 %
// intervals, correlations, warnings, the misfit before and after, the
// forecast), calibration.csv (the parameter table), calibration_fit.csv
// (every reading against the start and fitted curves) and calibrated.json
// (the project file with the fitted values).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "project/project.hpp"

namespace frostwall::calibrate {

struct CalibrateOptions {
  int jobs = 0;                                  // forward runs at once (0: one per core)
  int threads = 0;                               // OpenMP threads per run (0: the cores shared among the jobs)
  std::string project_text;                      // the project file as given
  std::function<void(const std::string&)> note;  // one line per stage and iteration
  std::function<void(double, double)> progress;  // the forecast run's
};

// Throws project::ProjectError (before any work) for a project without
// "calibrate", sensors inside a pipe, and what `frostwall run` refuses.
void check_calibration(const project::Project& p);

// One line for `frostwall check`: the readings and the parameters to fit.
std::string describe_calibration(const project::Project& p);

// Returns the summary written (with its "calibration" block).
nlohmann::ordered_json run_calibration(const project::Project& p, const CalibrateOptions& options);

}  // namespace frostwall::calibrate
