// The forward model of a calibration: the project run as `frostwall run`
// runs it (same cloud, kernel, integrator, time steps), quietly, with the
// sensors read at the exact times of the readings by the run's own sensor
// model (freezing/thermometers.hpp). Many runs go side by side.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <vector>

#include "freezing/model.hpp"
#include "project/project.hpp"
#include "summary/summary.hpp"

namespace frostwall::calibrate {

struct ForwardResult {
  std::vector<double> temperatures;  // degC, one per reading, in the readings' order
  summary::Summary summary;          // the run's summary (closure, wall, ...)
};

// Runs p into `scratch` without VTK, report or error estimate, removes the
// files afterwards, and reads the sensors at the readings' times. With
// readings, the run ends at the step that passes the last one (its steps
// until then are those of the whole run: the step limits follow
// time.end); without, it runs to time.end. With `cloud` (freezing::build_cloud of p's geometry), a
// copy of it is run instead of placing the particles again.
ForwardResult run_forward(project::Project p, const std::vector<project::Reading>& readings,
                          const std::filesystem::path& scratch, const freezing::Model* cloud = nullptr);

// Runs the tasks `jobs` at a time, each on `threads` OpenMP threads, and
// returns their results in order; the first failure is rethrown.
std::vector<ForwardResult> side_by_side(const std::vector<std::function<ForwardResult()>>& tasks, int jobs,
                                        int threads);

}  // namespace frostwall::calibrate
