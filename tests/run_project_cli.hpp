// Runs `frostwall run` on a project in a fresh temporary directory (its
// output directory must be "out") and returns summary.json; `inspect` sees
// the output directory before it is removed.
#pragma once

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <sys/wait.h>

#include "temp_dir.hpp"

namespace frostwall::test {

// options: extra command-line options, e.g. "--threads 1".
inline nlohmann::json run_project(const nlohmann::json& project,
                                  const std::function<void(const std::filesystem::path&)>& inspect = {},
                                  const std::string& options = "") {
  TempDir dir;
  std::ofstream(dir.path / "p.json") << project.dump(2);
  const std::string line = "cd '" + dir.path.string() + "' && '" FROSTWALL_EXE "' " + options + " run p.json > log.txt 2>&1";
  const int status = std::system(line.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::ifstream in(dir.path / "out" / "summary.json");
  if (inspect) inspect(dir.path / "out");
  return nlohmann::json::parse(in);
}

}  // namespace frostwall::test
