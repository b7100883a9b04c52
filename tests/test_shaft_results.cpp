// Story: what an engineer reads. A coarse single-ring run (10 cm, 20 days)
// through run_project must write the summary of the contract
// (project-format.md section 2: every field, its type, null where nothing
// is frozen), CSV files with fixed headers, and front curves that VTK reads
// back: before closure the full ring has one closed front around each of
// the 26 pipes; after closure the wall has two closed fronts, inner and
// outer. Quantities are checked against the geometry they must obey.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::string first_line(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

bool number_or_null(const json& v) { return v.is_null() || v.is_number(); }

// Closed polylines of a .vtp: cells whose last point id repeats the first.
std::pair<int, int> closed_and_open(const fs::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkCellArray* lines = reader->GetOutput()->GetLines();
  int closed = 0, open = 0;
  vtkIdType n;
  const vtkIdType* ids;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);) (n > 2 && ids[0] == ids[n - 1] ? closed : open)++;
  return {closed, open};
}

}  // namespace

TEST_CASE("A shaft run writes the summary of the contract, CSV files and front curves", "[freezing][results]") {
  test::TempDir dir("frostwall-results");
  auto p = test::shipped_project(
      "single_ring_sand.json",
      {{"numerics", {{"spacing", 0.1}, {"integrator", "explicit"}, {"placement", "lattice"}}},
       {"time", {{"end", 20}, {"unit", "d"}, {"snapshots", {10, 20}}}},
       {"monitoring", {{{"name", "C1"}, {"r", 5.0}, {"theta_deg", 6.923}}, {{"name", "C2"}, {"x", -4.0}, {"y", 1.0}}}},
       {"output", {{"directory", (dir.path / "out").string()}, {"vtk", false}}}});
  run::run_project(p, {});
  const fs::path out = dir.path / "out";
  std::ifstream in(out / "summary.json");
  const json s = json::parse(in);

  // ---- the contract, field by field
  CHECK(s["project"] == "Single ring, 26 pipes, medium-coarse sand");
  CHECK(s["frostwall_version"] == "0.1.0");
  REQUIRE(s["closure_time_days"].is_number());
  const double closure = s["closure_time_days"];
  CHECK(closure > 10.0);
  CHECK(closure < 20.0);
  // The columns touch (half frozen) before a fully frozen path joins them.
  REQUIRE(s["front_contact_days"].is_number());
  CHECK(s["front_contact_days"] > 5.0);
  CHECK(s["front_contact_days"] < closure);
  REQUIRE(s["wall"].size() == 2);
  for (const auto& w : s["wall"]) {
    CHECK(w["day"].is_number());
    for (const char* plane : {"OA", "OB"}) {
      CHECK(number_or_null(w[plane]["inner"]));
      CHECK(number_or_null(w[plane]["outer"]));
      CHECK(w[plane]["thickness"].is_number());
    }
    CHECK(w["min_thickness"].is_number());
    CHECK(number_or_null(w["mean_temperature_OB"]));
  }
  const auto& day10 = s["wall"][0];
  const auto& day20 = s["wall"][1];
  // Before closure: OA crosses a frozen column, OB (between pipes) nothing.
  CHECK(day10["OA"]["thickness"] > 0.0);
  CHECK(day10["OB"]["inner"].is_null());
  CHECK(day10["OB"]["thickness"] == 0.0);
  CHECK(day10["min_thickness"] == 0.0);
  CHECK(day10["mean_temperature_OB"].is_null());
  // After closure: the wall holds the ring radius on both planes, OB is
  // thinner than OA (between pipes), the weakest ray is no thicker than OB,
  // and the frozen wall is below the freezing point and above the pipe.
  for (const char* plane : {"OA", "OB"}) {
    CHECK(day20[plane]["inner"] < 5.0);
    CHECK(day20[plane]["outer"] > 5.0);
    CHECK(day20[plane]["thickness"] == Approx(double(day20[plane]["outer"]) - double(day20[plane]["inner"])));
  }
  CHECK(day20["OB"]["thickness"] < day20["OA"]["thickness"]);
  CHECK(day20["min_thickness"] <= double(day20["OB"]["thickness"]) + 1e-9);
  CHECK(day20["min_thickness"] > 0.0);
  CHECK(day20["mean_temperature_OB"] < 0.0);
  CHECK(day20["mean_temperature_OB"] > -20.0);

  CHECK(s["design"]["required_thickness"] == 2.5);
  CHECK(s["design"]["pass"] == false);  // 20 days is far too short for 2.5 m
  CHECK(s["design"]["reached_day"].is_null());

  // Sensors: one reading per output interval, starting warm and cooling;
  // C1 sits on OB at the ring, C2 far inside, which cools less.
  REQUIRE(s["monitoring"]["C1"].size() >= 100);
  const auto& c1 = s["monitoring"]["C1"];
  const auto& c2 = s["monitoring"]["C2"];
  CHECK(c1.back()[0] == Approx(20.0));
  CHECK(c1.back()[1] < c1.front()[1]);
  CHECK(c1.back()[1] < c2.back()[1]);

  REQUIRE(s["interface"].size() == 2);
  for (const auto& entry : s["interface"]) CHECK(fs::exists(out / std::string(entry["file"])));
  for (const char* key : {"particles", "steps"}) CHECK(s["run"][key].is_number_integer());
  CHECK(s["run"]["wall_seconds"].is_number());
  CHECK(s["run"]["integrator"] == "explicit");
  CHECK(s["run"]["spacing"] == 0.1);
  CHECK(s["warnings"].is_array());

  // ---- CSV headers
  CHECK(first_line(out / "wall.csv") ==
        "day,OA_inner_m,OA_outer_m,OA_thickness_m,OB_inner_m,OB_outer_m,OB_thickness_m,min_thickness_m,"
        "mean_temperature_OB_C");
  CHECK(first_line(out / "profiles_OA.csv") == "r_m,T_day_10_C,T_day_20_C");
  CHECK(first_line(out / "profiles_OB.csv") == "r_m,T_day_10_C,T_day_20_C");
  CHECK(first_line(out / "monitoring.csv") == "day,C1_C,C2_C");

  // ---- profiles: inside OA's pipe (r = 5 +- 0.0635 m) the pipe's -20 C,
  // not the layers held beyond its wall; the axis has a value (this lattice
  // wedge's narrow apex holds no particle within a support of it), the
  // warm ground's, close to that of the next point out.
  {
    std::ifstream csv(out / "profiles_OA.csv");
    std::string line;
    std::getline(csv, line);
    std::map<double, std::vector<std::string>> rows;
    while (std::getline(csv, line)) {
      std::vector<std::string> cells;
      std::stringstream cell(line);
      for (std::string c; std::getline(cell, c, ',');) cells.push_back(c);
      rows[std::round(std::stod(cells[0]) * 100.0) / 100.0] = cells;
    }
    for (double r : {4.95, 5.0, 5.05}) {
      REQUIRE(rows.count(r));
      for (std::size_t k = 1; k <= 2; ++k) CHECK(std::stod(rows[r][k]) == -20.0);
    }
    REQUIRE(rows[0.0].size() == 3);
    for (std::size_t k = 1; k <= 2; ++k) {
      REQUIRE_FALSE(rows[0.0][k].empty());
      CHECK(std::stod(rows[0.0][k]) > 10.0);
      CHECK(std::abs(std::stod(rows[0.0][k]) - std::stod(rows[0.25][k])) < 0.05);
    }
    // Just outside the pipe wall the ground is above the pipe's temperature.
    CHECK(std::stod(rows[5.1][2]) > -20.0);
  }

  // ---- front curves of the full ring
  const auto [closed10, open10] = closed_and_open(out / std::string(s["interface"][0]["full_ring_file"]));
  const auto [closed20, open20] = closed_and_open(out / std::string(s["interface"][1]["full_ring_file"]));
  fmt::print("\nFull-ring fronts: day 10 {} closed / {} open, day 20 {} closed / {} open\n", closed10, open10, closed20,
             open20);
  CHECK(closed10 == 26);  // one around each pipe
  CHECK(open10 == 0);
  CHECK(closed20 == 2);  // the wall's inner and outer face
  CHECK(open20 == 0);
}

// A double ring closes when its inner ring's columns join (the four-hole:
// about a day in), long before the frozen stretch of the outer ring reaches
// the inner one. The thinnest wall is the longest frozen stretch on a ray
// that contains a ring of pipes, so it is positive from closure on (the
// inner ring's stretch alone until both merge), never 0 while the shaft is
// already cut off from the far field.
TEST_CASE("A double ring's thinnest wall is positive from closure on", "[freezing][results]") {
  test::TempDir dir("frostwall-four-hole");
  auto p = test::shipped_project(
      "four_hole_sand.json",
      {{"numerics", {{"spacing", 0.03}}},
       {"time", {{"end", 4}, {"unit", "d"}, {"snapshots", {1, 2, 4}}}},
       {"output", {{"directory", (dir.path / "out").string()}, {"vtk", false}, {"report", false}}}});
  run::run_project(p, {});
  std::ifstream in(dir.path / "out" / "summary.json");
  const json s = json::parse(in);
  REQUIRE(s["closure_time_days"].is_number());
  const double closure = s["closure_time_days"];
  std::ifstream csv(dir.path / "out" / "wall.csv");
  std::string line;
  std::getline(csv, line);
  int after = 0, positive = 0;
  double first_after = -1.0;
  while (std::getline(csv, line)) {
    std::stringstream cells(line);
    std::vector<std::string> c;
    for (std::string v; std::getline(cells, v, ',');) c.push_back(v);
    const double day = std::stod(c[0]), thinnest = std::stod(c[7]);
    if (day < closure) continue;
    if (first_after < 0.0) first_after = thinnest;
    ++after;
    positive += thinnest > 0.0;
  }
  fmt::print("\nFour-hole (3 cm): closure day {:.3f}; thinnest wall at the first row after it {:.3f} m, "
             "{} of {} rows after closure positive; at day 4 {:.3f} m\n",
             closure, first_after, positive, after, double(s["wall"][2]["min_thickness"]));
  REQUIRE(after > 100);
  CHECK(positive == after);
  // Day 1 may be before closure; day 2 and 4 are after it and the wall grows.
  CHECK(s["wall"][1]["min_thickness"] > 0.0);
  CHECK(s["wall"][2]["min_thickness"] > s["wall"][1]["min_thickness"]);
  // Still the inner ring's stretch alone at day 2: thinner than the 0.8 m
  // between the rings plus the outer columns' reach would make it.
  CHECK(s["wall"][1]["min_thickness"] < 0.8);
}
