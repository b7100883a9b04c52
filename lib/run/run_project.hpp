// One run of a project, end to end: geometry -> particles -> SPH model ->
// time loop -> VTK snapshots, post-processing and summary.json.
#pragma once

#include <functional>
#include <string>

#include "project/project.hpp"

namespace frostwall::run {

struct RunOptions {
  // Called after every step with (t, t_end) in seconds; may be empty.
  std::function<void(double, double)> progress;
  // Called with one-line notes worth telling the user (wedge chosen, spacing fitted).
  std::function<void(const std::string&)> note;
  // The project file's text as given; written as project.json so that the
  // report can be rebuilt from the output directory alone. May be empty.
  std::string project_text;
};

// Throws project::ProjectError naming output.directory when it could not
// be created (a file in its path, no permission); creates nothing.
void check_output_directory(const std::string& directory);

// Writes everything into project.output.directory (created if needed).
// Throws project::ProjectError for input that cannot be run (before any
// output is written) and std::runtime_error for failures during the run.
void run_project(const project::Project& project, const RunOptions& options);

}  // namespace frostwall::run
