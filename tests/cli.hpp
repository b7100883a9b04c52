// Running the frostwall command from a test: exit status and stderr lines.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <sys/wait.h>

namespace frostwall::test {

struct CliRun {
  int exit_status = -1;
  std::vector<std::string> stderr_lines;
};

// `frostwall <arguments>` with `dir` as working directory; stdout and
// stderr go to files in `dir`.
inline CliRun frostwall_cli(const std::filesystem::path& dir, const std::string& arguments) {
  const std::string command = "cd '" + dir.string() + "' && '" FROSTWALL_EXE "' " + arguments +
                              " >cli_stdout.txt 2>cli_stderr.txt";
  const int status = std::system(command.c_str());
  CliRun run;
  if (status != -1 && WIFEXITED(status)) run.exit_status = WEXITSTATUS(status);
  std::ifstream in(dir / "cli_stderr.txt");
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) run.stderr_lines.push_back(line);
  return run;
}

}  // namespace frostwall::test
