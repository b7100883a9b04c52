// The shaft as built: a survey turned into pipe traces (minimum curvature
// against hand cases), sections at depth run on the full ring, a failed
// pipe, the 3-D view, bad survey input, and the depths spread over MPI
// ranks. Scaled sections: 8 pipes on a 1.2 m ring.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "cli.hpp"
#include "geometry/as_built.hpp"
#include "geometry/survey.hpp"
#include "report/mustache_view.hpp"
#include "report/report.hpp"
#include "report/templates.hpp"
#include "report_view_check.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using frostwall::test::TempDir;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double ring_radius = 1.2;
constexpr int pipe_count = 8;

json scaled_ring(double spacing, double end_day) {
  return {{"name", "scaled ring"},
          {"layout",
           {{"pattern", "single"},
            {"outer_ring", {{"radius", ring_radius}, {"count", pipe_count}, {"start_angle_deg", 0.0}}}}},
          {"shaft", {{"excavation_radius", 0.7}}},
          {"pipe", {{"diameter", 0.127}, {"temperature", -25.0}}},
          {"soil", "sand"},
          {"domain", {{"outer_radius", 4.0}, {"initial_temperature", 8.0}, {"far_field", {{"temperature", 8.0}}}}},
          {"time", {{"end", end_day}, {"unit", "d"}, {"snapshots", {end_day / 2, end_day}}}},
          {"numerics", {{"spacing", spacing}}},
          {"output", {{"directory", "out"}, {"vtk", true}, {"report", true}}}};
}

// Design centre of pipe k (from 1).
std::array<double, 2> design_centre(int k) {
  const double a = 2 * pi * (k - 1) / pipe_count;
  return {ring_radius * std::cos(a), ring_radius * std::sin(a)};
}

// The project and its survey (survey.csv) in a fresh folder.
void write(const fs::path& dir, const json& project, const std::string& survey) {
  std::ofstream(dir / "p.json") << project.dump(2);
  if (!survey.empty()) std::ofstream(dir / "survey.csv") << survey;
}

json run_in(const fs::path& dir, const std::string& launcher = "") {
  frostwall::test::CliOptions o;
  o.launcher = launcher;
  frostwall::test::require_frostwall(dir, "run p.json", o);
  std::ifstream in(dir / "out" / "summary.json");
  return json::parse(in);
}

// Every pipe's centre at the depths, shifted by (dx, dy) per metre of depth.
std::string positions_csv(const std::vector<double>& depths, double dx_per_m, double dy_per_m, int pushed = 0,
                          double push = 0.0) {
  std::string csv = "pipe,depth,x,y\n";
  for (int k = 1; k <= pipe_count; ++k)
    for (const double d : depths) {
      auto c = design_centre(k);
      if (k == pushed) {
        const double a = std::atan2(c[1], c[0]);
        c = {(ring_radius + push) * std::cos(a), (ring_radius + push) * std::sin(a)};
      }
      csv += fmt::format("{},{},{:.9f},{:.9f}\n", k, d, c[0] + dx_per_m * d, c[1] + dy_per_m * d);
    }
  return csv;
}

}  // namespace

TEST_CASE("As built check 3: minimum curvature gives a straight hole and a circular arc", "[as_built][geometry]") {
  using frostwall::geometry::minimum_curvature;
  SECTION("constant inclination and azimuth: a straight line from the collar") {
    const double I = 2.0, A = 135.0;  // degrees; azimuth clockwise from +y
    const std::vector<std::array<double, 3>> stations{{10, I, A}, {25, I, A}, {60, I, A}};
    const auto at = minimum_curvature({1.0, 2.0, 0.0}, stations);
    REQUIRE(at.size() == 3);
    for (std::size_t k = 0; k < 3; ++k) {
      const double md = stations[k][0], s = std::sin(I * pi / 180);
      CHECK(at[k][0] == Approx(1.0 + md * s * std::sin(A * pi / 180)).margin(1e-12));
      CHECK(at[k][1] == Approx(2.0 + md * s * std::cos(A * pi / 180)).margin(1e-12));
      CHECK(at[k][2] == Approx(md * std::cos(I * pi / 180)).margin(1e-12));
    }
  }
  SECTION("a constant build rate from the vertical: a circular arc") {
    // Inclination grows 3 degrees per 10 m, azimuth east (+x): radius 10 m / (3 deg).
    const double rate = 3.0 * pi / 180 / 10.0, R = 1.0 / rate;
    std::vector<std::array<double, 3>> stations;
    for (int k = 0; k <= 12; ++k) stations.push_back({10.0 * k, 3.0 * k, 90.0});
    const auto at = minimum_curvature({0.0, 0.0, 0.0}, stations);
    for (std::size_t k = 0; k < stations.size(); ++k) {
      const double I = stations[k][1] * pi / 180;
      CHECK(at[k][0] == Approx(R * (1 - std::cos(I))).margin(1e-9));
      CHECK(at[k][1] == Approx(0.0).margin(1e-12));
      CHECK(at[k][2] == Approx(R * std::sin(I)).margin(1e-9));
    }
  }
}

TEST_CASE("As built check 2: one pipe pushed out gives the hand geometry's gap and a later closure",
          "[as_built][freezing][cli]") {
  const double push = 0.15;
  TempDir straight, pushed;
  write(straight.path, scaled_ring(0.03, 12), "");
  json p = scaled_ring(0.03, 12);
  p["survey"] = {{"file", "survey.csv"}};
  p["sections"] = {{"depths", {20}}};
  write(pushed.path, p, positions_csv({10, 30}, 0, 0, 1, push));
  const json ring = run_in(straight.path), built = run_in(pushed.path);
  REQUIRE(built["sections"].size() == 1);
  const json& s = built["sections"][0];
  // Pipe 1 at r + push, its neighbours at r, 45 degrees either side: wall to wall.
  const double r = ring_radius, q = r + push, phi = 2 * pi / pipe_count;
  const double hand = std::sqrt(r * r + q * q - 2 * r * q * std::cos(phi)) - 0.127;
  CHECK(s["largest_gap"].get<double>() == Approx(hand).margin(1e-3));
  REQUIRE(ring["closure_time_days"].is_number());
  REQUIRE(s["closure_time_days"].is_number());
  CHECK(s["closure_time_days"].get<double>() > ring["closure_time_days"].get<double>());
  CHECK(built["critical_depth"] == 20.0);
}

TEST_CASE("As built check 1: a ring shifted rigidly with depth closes as the straight ring at every depth",
          "[as_built][freezing][cli]") {
  // The straight ring placed as the sections are, without symmetry: a
  // mirror wedge's cloud puts rows symmetrically about the gaps, and
  // closure moves with where rows fall by about 1 % at this spacing.
  TempDir straight, tilted;
  json reference_ring = scaled_ring(0.025, 6);
  reference_ring["numerics"]["symmetry"] = "none";
  write(straight.path, reference_ring, "");
  json p = scaled_ring(0.025, 6);
  p["survey"] = {{"file", "survey.csv"}};
  p["sections"] = {{"depths", {10, 20}}};
  // Every pipe tilted 0.5 degrees towards azimuth 30 (clockwise from +y): stations.
  std::string csv = "pipe,depth,inclination_deg,azimuth_deg\n";
  for (int k = 1; k <= pipe_count; ++k) csv += fmt::format("{},5,0.5,30\n{},20,0.5,30\n", k, k);
  write(tilted.path, p, csv);
  const json ring = run_in(straight.path), built = run_in(tilted.path);
  const double reference = ring["closure_time_days"].get<double>();
  REQUIRE(built["sections"].size() == 2);
  for (const auto& s : built["sections"]) {
    INFO("depth " << s["depth"]);
    // The ring is shifted by depth * sin(0.5 deg), its shape unchanged.
    REQUIRE(s["closure_time_days"].is_number());
    CHECK(s["closure_time_days"].get<double>() == Approx(reference).epsilon(0.01));
    CHECK(s["largest_gap"].get<double>() == Approx(2 * ring_radius * std::sin(pi / pipe_count) - 0.127).margin(1e-6));
  }
  // The 3-D view: each section moved to its depth, every pipe's trace.
  const fs::path out = tilted.path / "out";
  std::ifstream vtm(out / "shaft.vtm");
  std::stringstream text;
  text << vtm.rdbuf();
  CHECK(text.str().find("shaft/section_010.00m.vtu") != std::string::npos);
  CHECK(text.str().find("shaft/section_020.00m.vtu") != std::string::npos);
  CHECK(text.str().find("shaft/pipes.vtp") != std::string::npos);
  CHECK(fs::file_size(out / "shaft" / "section_020.00m.vtu") > 1000);
  // The report shows the sections against depth.
  const json view = frostwall::report::report_view(out);
  CHECK(view["has_as_built"] == true);
  CHECK(view["as_built_charts"].size() == 4);
  CHECK(view["as_built_rows"].size() == 2);
  // Every name of the as-built section is in the view.
  frostwall::test::check_section_filled(view, "has_as_built");
}

TEST_CASE("As built check 4: a failed pipe puts the thinnest wall at its angle and closes later",
          "[as_built][freezing][cli]") {
  TempDir intact, failed;
  write(intact.path, scaled_ring(0.03, 30), "");
  json p = scaled_ring(0.03, 30);
  p["failed_pipes"] = {3};
  p["compare_intact"] = true;
  write(failed.path, p, "");
  const json ring = run_in(intact.path), off = run_in(failed.path);
  // The intact twin beside the scenario is the intact ring's own run.
  REQUIRE(off["intact"].is_object());
  CHECK(off["intact"]["closure_time_days"].get<double>() ==
        Approx(ring["closure_time_days"].get<double>()).epsilon(1e-12));
  CHECK(off["intact"]["thinnest_wall"].get<double>() ==
        Approx(ring["wall"].back()["min_thickness"].get<double>()).epsilon(1e-12));
  const json view = frostwall::report::report_view(failed.path / "out");
  CHECK(view["has_intact_pair"] == true);
  CHECK(view["intact_rows"].size() == 2);
  const auto block = frostwall::test::split_section(frostwall::report::templates::report_html, "has_intact_pair").first;
  for (const auto& name : frostwall::report::template_names(block)) {
    INFO(name);
    CHECK(frostwall::test::has_key(view, name));
  }
  CHECK(fs::exists(failed.path / "out" / "failed" / "field.pvd"));
  const double pipe_3 = 360.0 * 2 / pipe_count;  // degrees
  for (const auto& w : off["wall"]) {
    INFO("day " << w["day"]);
    CHECK(w["thinnest_angle_deg"].get<double>() == Approx(pipe_3).margin(360.0 / pipe_count / 4));
  }
  CHECK(off["thinnest_angle_deg"].get<double>() == Approx(pipe_3).margin(360.0 / pipe_count / 4));
  REQUIRE(ring["closure_time_days"].is_number());
  const json later = off["closure_time_days"];
  CHECK((later.is_null() || later.get<double>() > ring["closure_time_days"].get<double>()));
}

TEST_CASE("As built check 5: two MPI ranks give one rank's summary", "[as_built][mpi][cli]") {
  TempDir one, two;
  json p = scaled_ring(0.04, 6);
  p["survey"] = {{"file", "survey.csv"}};
  p["sections"] = {{"every", 15}};
  p["failed_pipes"] = {5};
  p["compare_intact"] = true;
  const std::string csv = positions_csv({10, 30}, 0.002, -0.001, 2, 0.1);
  write(one.path, p, csv);
  write(two.path, p, csv);
  json a = run_in(one.path), b = run_in(two.path, "mpirun --allow-run-as-root --oversubscribe -np 2");
  REQUIRE(a["sections"].size() == 2);
  CHECK(a["sections"][0].contains("intact"));
  // Everything but the wall times and thread counts.
  for (json* s : {&a, &b}) {
    (*s)["run"].erase("wall_seconds");
    (*s)["run"].erase("threads");
  }
  CHECK(a == b);
}

TEST_CASE("As built: bad surveys stop before any work with the file and line", "[as_built][cli][input]") {
  struct Case {
    const char* what;
    std::string csv;
    json patch;
    std::string expected;
  };
  const std::string good_rows = positions_csv({10, 20}, 0, 0);
  const std::vector<Case> cases{
      {"a pipe that does not exist", good_rows + "9,10,1.0,0.0\n", json::object(),
       "survey.file: survey.csv line 18: pipe 9 does not exist"},
      {"a pipe missing", good_rows.substr(0, good_rows.rfind("\n8,10,") + 1), json::object(),
       "survey.file: survey.csv pipe 8 is missing"},
      {"depths that do not increase", good_rows + "1,15,1.2,0\n", json::object(),
       "survey.file: survey.csv line 18: pipe 1's depth 15 does not increase"},
      {"a section below every pipe",
       good_rows,
       {{"sections", {{"depths", {10, 25}}}}},
       "sections.depths[1]: 25 m is below every pipe"},
      {"an inclination over 90 degrees", "pipe,depth,inclination_deg,azimuth_deg\n1,10,95,0\n", json::object(),
       "survey.file: survey.csv line 2: inclination 95 is outside 0 to 90 degrees"},
      {"a cell that is not a number", "pipe,depth,x,y\n1,10,abc,0\n", json::object(),
       "survey.file: survey.csv line 2: x 'abc' is not a number"},
  };
  for (const auto& c : cases) {
    INFO(c.what);
    TempDir dir;
    json p = scaled_ring(0.04, 6);
    p["survey"] = {{"file", "survey.csv"}};
    p.merge_patch(c.patch);
    write(dir.path, p, c.csv);
    const auto run = frostwall::test::frostwall_cli(dir.path, "run p.json");
    CHECK(run.exit_status == 2);
    std::string said;
    for (const auto& line : run.stderr_lines) said += line + "\n";
    INFO(said);
    CHECK(said.find(c.expected) != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));
  }
  SECTION("pipes that cross") {
    // Pipe 2 drifts onto pipe 1 at 20 m.
    std::string csv = "pipe,depth,x,y\n";
    for (int k = 1; k <= pipe_count; ++k) {
      const auto c = design_centre(k);
      csv += fmt::format("{},10,{},{}\n", k, c[0], c[1]);
      const auto d = k == 2 ? design_centre(1) : c;
      csv += fmt::format("{},20,{},{}\n", k, k == 2 ? d[0] + 0.05 : d[0], d[1]);
    }
    TempDir dir;
    json p = scaled_ring(0.04, 6);
    p["survey"] = {{"file", "survey.csv"}};
    write(dir.path, p, csv);
    const auto run = frostwall::test::frostwall_cli(dir.path, "run p.json");
    CHECK(run.exit_status == 2);
    REQUIRE_FALSE(run.stderr_lines.empty());
    CHECK(run.stderr_lines.size() == 1);
    CHECK(run.stderr_lines.front().find("survey.file: survey.csv lines 3 and 5:") == 0);
    CHECK(run.stderr_lines.front().find("pipes 1 and 2 cross") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));
  }
}
