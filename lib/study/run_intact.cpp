#include "study/run_intact.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "io/output_directory.hpp"
#include "study/run_sections.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;
using nlohmann::json;
namespace keys = summary::keys;

StudyRun run_with_intact(const project::Project& p, const std::string& project_text, const StudyOptions& options) {
  io::check_output_directory(p.output.directory);
  const fs::path out = p.output.directory;
  const auto& failed = std::get<project::ShaftSection>(p.geometry).layout.failed_pipes;
  const json base = json::parse(project_text);
  json scenario = base, intact = base;
  scenario.erase("compare_intact");
  scenario["output"]["directory"] = (out / "failed").string();
  intact.erase("compare_intact");
  intact.erase("failed_pipes");
  intact["name"] = p.name + " (intact)";
  intact["output"]["directory"] = (out / "intact").string();
  project::parse_project(intact.dump(), "intact");  // loads before anything runs
  Study study;
  study.name = p.name;
  study.output_directory = out;
  study.estimate_errors = false;
  study.variants = {{"failed", fmt::format("pipes {} failed", fmt::join(failed, ", ")), scenario},
                    {"intact", "every pipe working", intact}};
  fs::create_directories(out);
  StudyRun run = run_study(study, options);
  for (const auto& v : run.variants)
    if (!v.ok) throw std::runtime_error(fmt::format("{}: {}", v.name, v.errors.empty() ? "failed" : v.errors.front()));
  if (!run.writer) return run;

  json summary = run.variants[0].summary;
  summary[keys::project] = p.name;
  summary[keys::scenario_directory] = "failed";
  summary[keys::design_margin] = design_margin(summary);
  summary[keys::intact] = wall_digest(run.variants[1].summary);
  summary[keys::intact]["directory"] = "intact";
  write_joined_run(p, project_text, summary);
  return run;
}

}  // namespace frostwall::study
