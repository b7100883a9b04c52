// The one sensor model of runs, calibration and the report
// (freezing/thermometers.hpp): linear on the Delaunay triangle round a
// sensor, as ParaView shows the files; linear in time between steps, the
// step held to keep that within numerics.sensor_tolerance.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "calibrate/forward.hpp"
#include "paths.hpp"
#include "post/triangle_probe.hpp"
#include "project/project.hpp"
#include "run/run_project.hpp"
#include "summary/summary.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using nlohmann::json;
using particles::Vec;

TEST_CASE("Triangle probe: a linear field is read exactly, images carry their source, off the cloud the nearest",
          "[thermometers]") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<2>> points;
  std::vector<std::uint32_t> source;
  for (std::uint32_t i = 0; i < 400; ++i) points.emplace_back(u(rng), u(rng)), source.push_back(i);
  // Images through the plane x = 0 of the points near it.
  for (std::uint32_t i = 0; i < 400; ++i)
    if (points[i][0] < 0.2) points.emplace_back(-points[i][0], points[i][1]), source.push_back(i);
  std::vector<double> field(400);
  for (std::uint32_t i = 0; i < 400; ++i) field[i] = 2.0 - 3.0 * points[i][0] + 5.0 * points[i][1];
  const std::vector<Vec<2>> where{{0.31, 0.47}, {0.9, 0.1}, {0.0, 0.5}, {-0.05, 0.3}, {3.0, 3.0}};
  const post::TriangleProbe probe(points, source, where);
  for (int k = 0; k < 2; ++k) CHECK(probe.at(k, field) == Approx(2.0 - 3.0 * where[k][0] + 5.0 * where[k][1]));
  // On the plane and across it the images carry their sources' values: a
  // field symmetric about the plane (linear in y alone) reads exactly.
  std::vector<double> along_plane(400);
  for (std::uint32_t i = 0; i < 400; ++i) along_plane[i] = 2.0 + 5.0 * points[i][1];
  CHECK(probe.at(2, along_plane) == Approx(2.0 + 5.0 * 0.5));
  CHECK(probe.at(3, along_plane) == Approx(2.0 + 5.0 * 0.3));
  double weights = 0.0;
  for (const auto& c : probe.corners(4)) weights += c.weight;
  CHECK(weights == Approx(1.0));
  CHECK(probe.corners(4).size() == 1);  // off the cloud: its nearest point
}

namespace {

json twin_ring() {
  json p = json::parse(std::ifstream(std::string(FROSTWALL_SOURCE_DIR) + "/tests/data/calibrate_twin_ring.json"));
  p.erase("calibrate");
  p["time"] = {{"end", 20}, {"unit", "d"}, {"snapshots", {10, 20}}};
  return p;
}

json run_ring(json p, const std::filesystem::path& dir) {
  auto project = project::parse_project(p.dump(), "ring", dir.string());
  project.output.directory = (dir / "out").string();
  return json::parse(summary::to_json(run::run_project(project, {})).dump());
}

}  // namespace

TEST_CASE("Thermometers: a run's monitoring and calibration's forward run read the same temperature at each time",
          "[thermometers]") {
  const json p = twin_ring();
  test::TempDir dir("frostwall-thermometers");
  const json run = run_ring(p, dir.path);
  // The forward run of calibration, asked for every monitoring sample.
  std::vector<project::Reading> readings;
  std::vector<double> monitored;
  for (std::size_t s = 0; s < p["monitoring"].size(); ++s)
    for (const auto& row : run["monitoring"][p["monitoring"][s]["name"].get<std::string>()]) {
      readings.push_back({0, s, row[0].get<double>() * 86400.0, 0.0});
      monitored.push_back(row[1].get<double>());
    }
  const auto project = project::parse_project(p.dump(), "ring", dir.path.string());
  const auto forward = calibrate::run_forward(project, readings, dir.path / "forward");
  REQUIRE(forward.temperatures.size() == monitored.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < monitored.size(); ++k)
    worst = std::max(worst, std::abs(forward.temperatures[k] - monitored[k]));
  CHECK(worst < 1e-9);
}

// A reading taken while a particle next to the sensor ends freezing (its
// temperature then falls on the time scale h^2 / alpha, 0.02 d at 4 cm)
// moves most with the step; the others lie far within the tolerance.
TEST_CASE(
    "Thermometers: the readings converge as the sensor tolerance shrinks, and at the default 98 % lie within 0.01 K",
    "[thermometers]") {
  json p = twin_ring();
  test::TempDir dir("frostwall-thermometers-tolerance");
  auto readings = [&](double tolerance, const std::string& name) {
    p["numerics"]["sensor_tolerance"] = tolerance;
    const json s = run_ring(p, dir.path / name);
    std::vector<double> out;
    for (const auto& sensor : p["monitoring"])
      for (const auto& row : s["monitoring"][sensor["name"].get<std::string>()]) out.push_back(row[1].get<double>());
    return std::make_pair(out, s["run"]["steps"].get<int>());
  };
  const auto [fine, fine_steps] = readings(2e-6, "fine");
  const auto [standard, standard_steps] = readings(2e-4, "default");
  const auto [loose, loose_steps] = readings(2e-2, "loose");
  auto differences = [&](const std::vector<double>& a) {
    std::vector<double> d;
    for (std::size_t k = 0; k < a.size(); ++k) d.push_back(std::abs(a[k] - fine[k]));
    std::sort(d.begin(), d.end());
    return d;
  };
  const auto d_loose = differences(loose), d_standard = differences(standard);
  const std::size_t n = d_standard.size(), p95 = n * 95 / 100;
  INFO("steps: loose " << loose_steps << ", default " << standard_steps << ", fine " << fine_steps);
  INFO("from the finest, 95th percentile and largest: loose "
       << d_loose[p95] << ", " << d_loose.back() << " K; default " << d_standard[p95] << ", " << d_standard.back()
       << " K");
  CHECK(d_standard[p95] < 0.005);
  CHECK(std::count_if(d_standard.begin(), d_standard.end(), [](double d) { return d > 0.01; }) <= n / 50);
  CHECK(d_standard.back() < d_loose.back() / 3);
  CHECK(d_standard[p95] < d_loose[p95]);
  CHECK(standard_steps < fine_steps);
}
