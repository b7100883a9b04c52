// Calibration from the plant's return temperature (sensor "return"): a twin
// of the calibration checks' scaled ring with a plant at -30 C, its sand's
// unfrozen conductivity 1.15 times the shipped sand's, run by `frostwall
// run`; the return temperatures its plant reported to day 20, with 0.02 K
// of noise of a fixed seed, are the only readings. The fit recovers the
// factor within 3 %, its interval holds it, and its misfit is the noise's.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "calibrate/run_calibrate.hpp"
#include "paths.hpp"
#include "project/project.hpp"
#include "run/run_project.hpp"
#include "summary/summary.hpp"
#include "temp_dir.hpp"
#include "twin_inputs.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace frostwall;

namespace {

json ring_with_plant() {
  json p = json::parse(std::ifstream(std::string(FROSTWALL_SOURCE_DIR) + "/tests/data/calibrate_twin_ring.json"));
  p["pipe"] = test::coaxial_pipe(30);
  p["brine"] = {{"flow_per_pipe", 1.5}};
  p["plant"] = {{"supply_temperature", -30}};
  p["calibrate"] = {{"readings", "readings.csv"}, {"parameters", {{"conductivity_unfrozen", {0.5, 2.0}}}}};
  return p;
}

// The twin's return temperatures to day `until`, noisy.
std::string twin_returns(const json& project, double factor, double until) {
  test::TempDir dir("frostwall-plant-twin");
  json twin = project;
  twin.erase("calibrate");
  twin["soil"] = test::scaled_sand(1.0, factor, 1.0);
  auto p = project::parse_project(twin.dump(), "twin", dir.path.string());
  p.output.directory = (dir.path / "out").string();
  const json s = json::parse(summary::to_json(run::run_project(p, {})).dump());
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.02);
  std::string csv = "sensor,time,temperature\n";
  for (const auto& row : s["plant"]["series"])
    if (row["day"].get<double>() <= until)
      csv += fmt::format("return,{:.9g},{:.5f}\n", row["day"].get<double>(),
                         row["return_temperature"].get<double>() + noise(rng));
  return csv;
}

}  // namespace

TEST_CASE("Calibration from the plant's return temperature: a twin's unfrozen conductivity recovered",
          "[plant][calibrate]") {
  const json project = ring_with_plant();
  test::TempDir dir("frostwall-plant-calibrate");
  std::ofstream(dir.path / "readings.csv") << twin_returns(project, 1.15, 20.0);
  auto p = project::parse_project(project.dump(), "plant twin", dir.path.string());
  p.output.directory = (dir.path / "out").string();
  calibrate::CalibrateOptions o;
  o.project_text = project.dump();
  const json c = json::parse(calibrate::run_calibration(p, o).dump())["calibration"];
  INFO(c.dump(1));
  const auto& q = c["parameters"]["conductivity_unfrozen"];
  fmt::print("\nCalibration from the return: conductivity_unfrozen {:.4f} ({:.4f} - {:.4f}) against 1.15; rms misfit "
             "{:.4f} K after, {:.4f} K before\n",
             q["value"].get<double>(), q["low"].get<double>(), q["high"].get<double>(),
             c["rms_misfit_after"].get<double>(), c["rms_misfit_before"].get<double>());
  CHECK(q["value"].get<double>() == Approx(1.15).epsilon(0.03));
  CHECK(q["low"].get<double>() <= 1.15);
  CHECK(q["high"].get<double>() >= 1.15);
  CHECK(c["rms_misfit_after"].get<double>() < 0.03);
  CHECK(c["sensors"].back() == "return");
}
