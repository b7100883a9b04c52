// A shipped project (projects/<name>) patched small (JSON merge patch: a
// null removes a key), run into `out` as `frostwall run` runs it, with
// project.json recorded, and its report written.
#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "report/report.hpp"
#include "run/run_project.hpp"
#include "paths.hpp"

namespace frostwall::test {

// The shipped project patched, its output in `out`, as the loader reads it.
inline project::Project shipped_project(const std::string& name, const nlohmann::json& patch,
                                        const std::filesystem::path& out) {
  std::ifstream in(std::filesystem::path(FROSTWALL_SOURCE_DIR) / "projects" / name);
  nlohmann::json j = nlohmann::json::parse(in);
  j.merge_patch(patch);
  j["output"]["directory"] = out.string();
  return project::parse_project(j.dump());
}

inline void run_shipped(const std::string& name, const nlohmann::json& patch, const std::filesystem::path& out) {
  std::ifstream in(std::filesystem::path(FROSTWALL_SOURCE_DIR) / "projects" / name);
  nlohmann::json j = nlohmann::json::parse(in);
  j.merge_patch(patch);
  j["output"]["directory"] = out.string();
  run::RunOptions options;
  options.project_text = j.dump();
  run::run_project(project::parse_project(options.project_text), options);
  report::write_report(out);
}

}  // namespace frostwall::test
