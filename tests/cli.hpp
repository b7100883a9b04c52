// Running the frostwall command from a test: the one helper every test that
// runs the program uses. The command runs in `dir` (its working directory)
// with stdout and stderr in dir/cli_stdout.txt and dir/cli_stderr.txt.
#pragma once

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "temp_dir.hpp"
#include "paths.hpp"

namespace frostwall::test {

struct CliRun {
  int exit_status = -1;
  std::vector<std::string> stderr_lines;
};

struct CliOptions {
  std::string launcher;     // e.g. "mpirun -n 2", before the program
  int timeout_seconds = 0;  // > 0: killed after this long (exit status 124)
};

// `[launcher] frostwall <arguments>` in dir.
inline CliRun frostwall_cli(const std::filesystem::path& dir, const std::string& arguments, const CliOptions& o = {}) {
  const std::string timeout = o.timeout_seconds > 0 ? "timeout " + std::to_string(o.timeout_seconds) + " " : "";
  const std::string command = "cd '" + dir.string() + "' && " + timeout + o.launcher + (o.launcher.empty() ? "" : " ") +
                              "'" + std::string(FROSTWALL_EXE) + "' " + arguments + " >cli_stdout.txt 2>cli_stderr.txt";
  const int status = std::system(command.c_str());
  CliRun run;
  if (status != -1 && WIFEXITED(status)) run.exit_status = WEXITSTATUS(status);
  std::ifstream in(dir / "cli_stderr.txt");
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) run.stderr_lines.push_back(line);
  return run;
}

// The same, and it must succeed (what it printed is shown when it does not).
inline void require_frostwall(const std::filesystem::path& dir, const std::string& arguments,
                              const CliOptions& o = {}) {
  const CliRun run = frostwall_cli(dir, arguments, o);
  std::ostringstream said;
  for (const auto& line : run.stderr_lines) said << line << "\n";
  INFO("frostwall " << arguments << " said:\n" << said.str());
  REQUIRE(run.exit_status == 0);
}

// `frostwall [options] run` on a project in a fresh temporary directory (its
// output directory must be "out"); returns summary.json. `inspect` sees the
// output directory before it is removed. options: e.g. "--threads 1".
inline nlohmann::json run_project(const nlohmann::json& project,
                                  const std::function<void(const std::filesystem::path&)>& inspect = {},
                                  const std::string& options = "") {
  TempDir dir;
  std::ofstream(dir.path / "p.json") << project.dump(2);
  require_frostwall(dir.path, options + " run p.json");
  std::ifstream in(dir.path / "out" / "summary.json");
  if (inspect) inspect(dir.path / "out");
  return nlohmann::json::parse(in);
}

}  // namespace frostwall::test
