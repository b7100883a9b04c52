// `frostwall check`: every shipped project passes it quickly, printing its
// particle or grain count and writing nothing; the count is the run's
// (a hand count for the PD plate's lattice).
#include <catch2/catch.hpp>

#include "cli.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {

const fs::path projects_dir = fs::path(FROSTWALL_SOURCE_DIR) / "projects";

struct Check {
  int exit_status = -1;
  std::string out;  // stdout
  double seconds = 0.0;
};

Check check(const fs::path& dir, const fs::path& file) {
  const auto start = std::chrono::steady_clock::now();
  const auto run = frostwall::test::frostwall_cli(dir, "check '" + file.string() + "'", {"", 60});
  Check c{run.exit_status, {}, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
  std::ifstream in(dir / "cli_stdout.txt");
  c.out.assign(std::istreambuf_iterator<char>(in), {});
  return c;
}

// The first whole number after `label` in the text, or -1.
long number_after(const std::string& text, const std::string& label) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(label + R"( (\d+))"))) return -1;
  return std::stol(m[1].str());
}

// Checks each shipped project file whose name passes `take`.
void check_shipped(const std::function<bool(const std::string&)>& take, double seconds) {
  int projects = 0;
  for (const auto& entry : fs::directory_iterator(projects_dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".json" || name.starts_with("study_") || !take(name))
      continue;  // study files run with `study`
    ++projects;
    INFO(name);
    frostwall::test::TempDir dir;
    const Check c = check(dir.path, entry.path());
    INFO(c.out);
    CHECK(c.exit_status == 0);
    CHECK((number_after(c.out, "particles:") > 0 || number_after(c.out, "grains:") > 0));
    CHECK(c.out.find("run time: ") != std::string::npos);
    CHECK(c.seconds < seconds);
    CHECK_FALSE(fs::exists(dir.path / "out"));
  }
  CHECK(projects >= 1);
}

// Shaft sections place a graded cloud of tens of thousands of particles
// (the seepage reference's half section: 45 000); the others take well
// under a second each.
bool graded_shaft(const std::string& name) {
  for (const char* shaft : {"single_ring", "three_hole", "four_hole", "seepage_reference", "shaft_layers", "as_built"})
    if (name.starts_with(shaft)) return true;
  return false;
}

}  // namespace

TEST_CASE("frostwall check passes the shipped plates and CFD-DEM cases, prints their counts and writes nothing",
          "[shared][cli][check]") {
  check_shipped([](const std::string& name) { return !graded_shaft(name) || name == "single_ring_sand.json"; }, 20.0);
}

TEST_CASE("frostwall check passes every shipped project", "[long][cli][check]") {
  check_shipped([](const std::string&) { return true; }, 60.0);
}

TEST_CASE("frostwall check counts the PD plate's particles as the run does", "[cli][check]") {
  // projects/plate_cooling.json: a 0.01 m square at 0.1 mm spacing; the two
  // held faces (top, right) sit on rows, the two others are mirrors halfway
  // between rows, so 0.01 / 0.0001 = 100 free rows each way.
  frostwall::test::TempDir dir;
  const Check c = check(dir.path, projects_dir / "plate_cooling.json");
  INFO(c.out);
  REQUIRE(c.exit_status == 0);
  CHECK(number_after(c.out, "particles:") == 100 * 100);
}

TEST_CASE("frostwall check gives the grains and DEM steps a short CFD-DEM run reports", "[cfd_dem][cli][check]") {
  // projects/verify_ergun.json, a held bed of 400 grains: the run's own
  // counts (LAMMPS' grain count and the steps it ran) in summary.json.
  frostwall::test::TempDir dir;
  const Check c = check(dir.path, projects_dir / "verify_ergun.json");
  INFO(c.out);
  REQUIRE(c.exit_status == 0);
  std::ofstream(dir.path / "p.json") << [] {
    std::ifstream in(projects_dir / "verify_ergun.json");
    auto p = nlohmann::json::parse(in);
    p["output"] = {{"directory", "out"}, {"vtk", false}, {"report", false}};
    return p.dump();
  }();
  frostwall::test::require_frostwall(dir.path, "run p.json", {"", 60});
  std::ifstream in(dir.path / "out" / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  CHECK(number_after(c.out, "grains:") == summary["grains"].get<long>());
  CHECK(number_after(c.out, "steps:") == summary["dem_steps"].get<long>());
}
