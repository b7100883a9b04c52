// Bad input through the command line: `frostwall run <file>` must stop with
// exit status 2, print every expected problem line to stderr and leave no
// output directory behind.
#include <catch2/catch.hpp>

#include "cli.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

const fs::path bad_dir = fs::path(FROSTWALL_SOURCE_DIR) / "tests" / "data" / "bad";
const fs::path layout_dir = fs::path(FROSTWALL_SOURCE_DIR) / "tests" / "data" / "bad_layout";
const fs::path run_dir = fs::path(FROSTWALL_SOURCE_DIR) / "tests" / "data" / "bad_run";

std::vector<std::string> lines_of(const fs::path& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

using ScratchDir = frostwall::test::TempDir;

struct Run {
  int exit_status = -1;
  std::vector<std::string> stderr_lines;
};

// Runs `frostwall run <file>` with `dir` as working directory, stopped
// after 10 s: bad input must be refused before any work (about 0.02 s
// each here), so a run that places particles or steps in time instead
// fails the test rather than hanging it (timeout's status is 124).
Run run_frostwall(const fs::path& dir, const std::string& file) {
  const auto cli = frostwall::test::frostwall_cli(dir, "run '" + file + "'", {"", 10});
  return {cli.exit_status, cli.stderr_lines};
}

bool contains(const std::vector<std::string>& lines, const std::string& line) {
  return std::find(lines.begin(), lines.end(), line) != lines.end();
}

}  // namespace

// bad/: the loader finds the problem; bad_layout/: a valid file whose pipe
// layout cannot be modelled (found when the section is built, before any
// output); bad_run/: a valid file the run refuses before any work (more
// particles than the machine holds, an output directory that cannot be
// made). All must stop with status 2 and write nothing.
TEST_CASE("bad project files stop the run with status 2 and write nothing", "[shared][cli]") {
  int cases = 0;
  for (const fs::path& bad_dir : {bad_dir, layout_dir, run_dir})
    for (const auto& entry : fs::directory_iterator(bad_dir)) {
      if (entry.path().extension() != ".json") continue;
      ++cases;
      const std::string name = entry.path().stem().string();
      const std::string file = entry.path().filename().string();
      INFO("bad case " << name);
      ScratchDir dir;
      fs::copy_file(entry.path(), dir.path / file);

      // `frostwall check` refuses it with the same lines and status.
      for (const char* command : {"run", "check"}) {
        INFO(command);
        const auto cli = frostwall::test::frostwall_cli(dir.path, std::string(command) + " '" + file + "'", {"", 10});
        CHECK(cli.exit_status == 2);
        for (const auto& expected : lines_of(bad_dir / (name + ".expected"))) {
          INFO("stderr:\n"
               << [&] {
                    std::string s;
                    for (const auto& l : cli.stderr_lines) s += l + "\n";
                    return s;
                  }());
          CHECK(contains(cli.stderr_lines, expected));
        }
        CHECK_FALSE(fs::exists(dir.path / "out" / ("bad_" + name)));
        CHECK_FALSE(fs::exists(dir.path / "out"));
      }
    }
  CHECK(cases >= 55);
}

// Without numerics.max_particles the limit comes from this machine's
// memory (freezing/capacity.hpp): a micrometre spacing is far beyond any.
TEST_CASE("a project the machine cannot hold is refused before any work", "[shared][cli]") {
  ScratchDir dir;
  {
    std::ifstream in(run_dir / "spacing_too_fine.json");
    auto project = nlohmann::json::parse(in);
    REQUIRE(project["numerics"].erase("max_particles") == 1);
    std::ofstream(dir.path / "fine.json") << project.dump(2);
  }
  const Run run = run_frostwall(dir.path, "fine.json");
  CHECK(run.exit_status == 2);
  REQUIRE(run.stderr_lines.size() == 1);
  const std::string& line = run.stderr_lines.front();
  INFO(line);
  CHECK(line.starts_with("numerics.spacing: 0.000001 m needs about 2.6e12 particles (limit "));
  CHECK(line.find(", from this machine's memory); use a spacing of ") != std::string::npos);
  CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("a project file that does not exist stops the run with status 2", "[shared][cli]") {
  ScratchDir dir;
  const Run run = run_frostwall(dir.path, "missing.json");
  CHECK(run.exit_status == 2);
  CHECK(contains(run.stderr_lines, "missing.json: cannot read: No such file or directory"));
}
