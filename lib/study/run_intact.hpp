// A failed-pipe scenario beside the intact layout (compare_intact without a
// survey): the project as given into <output>/failed and with every pipe
// working into <output>/intact, side by side (over the ranks under
// mpirun). Beside them the scenario's summary with `intact` (the intact
// run's closure, thinnest wall, its angle and design margin) and
// `scenario_directory`, and the report.
#pragma once

#include <string>

#include "project/project.hpp"
#include "study/run_study.hpp"

namespace frostwall::study {

StudyRun run_with_intact(const project::Project& p, const std::string& project_text, const StudyOptions& options);

}  // namespace frostwall::study
