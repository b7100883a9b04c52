// The shaft as built: one full-ring section run per depth, with the pipes
// where the survey puts them there, run side by side as a study's variants
// (and spread over MPI ranks). Each into <output>/<section folder>; then
// beside them the as-built summary.json (the critical section's summary
// with `sections`, `critical_depth` and `as_built`), shaft.vtm (the
// sections at their depths and every pipe's trace in 3-D) and the report.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/project.hpp"
#include "study/run_study.hpp"

namespace frostwall::study {

// One section to run: its depth, and its project file.
struct SectionRun {
  double depth = 0.0;
  std::string folder;   // "depth_012.50m", or with "_intact"
  bool intact = false;  // the intact twin of a failed-pipe section
  nlohmann::json project;
};

// Every section's project file (intact twins after their section when
// compare_intact). Throws project::ProjectError on a survey no section can
// be built from, or a section that does not load, before anything runs.
std::vector<SectionRun> section_runs(const project::Project& p, const std::string& project_text);

// How far a run's wall at its last snapshot is from the design, as a share
// of each requirement, the smallest of: 1 - utilisation (strength check),
// the thinnest wall over the required thickness minus 1, and the mean
// temperature's distance below its limit over the limit's size (at least
// 1 K). Below 0 the design is not met; null without a target.
nlohmann::json design_margin(const nlohmann::json& summary);

// A run's headline at its last snapshot: closure_time_days, thinnest_wall,
// thinnest_angle_deg, design_margin and the snapshot's day (null where
// missing).
nlohmann::json wall_digest(const nlohmann::json& summary);

// The index of the critical section among section summaries: the smallest
// design margin when every section has one, else the latest closure
// (never closed counts as latest).
std::size_t critical_section(const std::vector<nlohmann::json>& entries);

// `frostwall check` on an as-built project: the depths and what each runs.
std::vector<std::string> check_sections(const project::Project& p, const std::string& project_text);

StudyRun run_sections(const project::Project& p, const std::string& project_text, const StudyOptions& options);

}  // namespace frostwall::study
