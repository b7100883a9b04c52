#include "study/run_intact.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "io/atomic_file.hpp"
#include "io/output_directory.hpp"
#include "report/report.hpp"
#include "study/run_sections.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;
using nlohmann::json;

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
  const json& other = run.variants[1].summary;
  const json wall = other.value("wall", json::array());
  const json last = wall.empty() ? json::object() : wall.back();
  summary["project"] = p.name;
  summary["scenario_directory"] = "failed";
  summary["design_margin"] = design_margin(summary);
  summary["intact"] = {{"closure_time_days", other.value("closure_time_days", json())},
                       {"thinnest_wall", last.value("min_thickness", json())},
                       {"thinnest_angle_deg", last.value("thinnest_angle_deg", json())},
                       {"design_margin", design_margin(other)},
                       {"directory", "intact"}};
  io::write_text_file(out / "project.json", project_text);
  io::write_text_file(out / "summary.json", summary.dump(2) + "\n");
  if (p.output.report) report::write_report(out);
  return run;
}

}  // namespace frostwall::study
