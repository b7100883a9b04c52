// One run of a project: check that its output can be written, choose the
// engine the project asks for and run it. Each engine writes its files
// (VTK, CSV, summary.json) into project.output.directory; the report is
// written afterwards from those files by the caller (lib/report).
#pragma once

#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"

namespace frostwall::run {

using project::RunOptions;

enum class Engine { freezing, mechanics, cfd_dem };
Engine engine_of(const project::Project& p);

// The engine's run alone; run_project adds the error estimate when the
// project asks for it (run/error_estimate.hpp). Both return the summary
// written (empty on an MPI rank that writes none).
summary::Summary run_engine(const project::Project& p, const RunOptions& options);

// Throws project::ProjectError for input that cannot be run (before any
// output is written) and std::runtime_error for failures during the run.
summary::Summary run_project(const project::Project& p, const RunOptions& options);

}  // namespace frostwall::run
