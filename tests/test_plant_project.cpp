// The freezing plant from a project file, end to end.
//  - The shipped shaft with its plant (sand over clay, 120 kW, scaled):
//    run as `frostwall run` runs it; the plant's heat over the run equals
//    the heat the sections' own balances say left the ground through their
//    pipe walls, weighted by hand (each section stands for the pipe down to
//    halfway to the next); the last row's load is pipes x m c x (return -
//    supply) with the brine the summary says it took, and that brine is
//    calcium chloride's at the last interval's mean temperature; the load
//    never passes the capacity by more than the predictor's lag, the supply
//    starts well above and ends at its coldest, the deeper clay sees warmer
//    brine, and both sections close later than with the plant unlimited.
//  - One section with a plant at a flow too fast for the brine to warm
//    closes as the same section with its brine held at the supply behind
//    the same film (the constant-brine limit).
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.hpp"
#include "report/mustache_view.hpp"
#include "report/report.hpp"
#include "report/templates.hpp"
#include "report_view_check.hpp"
#include "project/cacl2_brine.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"
#include "twin_inputs.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// plant.csv's rows as numbers (the header skipped).
std::vector<std::vector<double>> plant_rows(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

// The shipped shaft with its plant, scaled, patched, run by the program.
json run_plant_shaft(const fs::path& dir, const json& patch) {
  std::ifstream in(fs::path(FROSTWALL_SOURCE_DIR) / "projects" / "shaft_plant.json");
  json j = json::parse(in);
  j.merge_patch({{"numerics", {{"spacing", 0.05}}},
                 {"time", {{"end", 60}, {"unit", "d"}, {"snapshots", {20, 60}}}},
                 {"output", {{"directory", "out"}, {"vtk", false}, {"report", true}}}});
  j.merge_patch(patch);
  std::ofstream(dir / "project.json") << j.dump(2);
  const auto run = frostwall::test::frostwall_cli(dir, "run project.json");
  REQUIRE(run.exit_status == 0);
  return read_json(dir / "out" / "summary.json");
}

}  // namespace

TEST_CASE(
    "The shipped shaft with its plant: the plant's heat is the sections', each row its brine's, the capacity held",
    "[plant][shipped]") {
  frostwall::test::TempDir dir("shaft_plant"), free_dir("shaft_plant_free");
  const json s = run_plant_shaft(dir.path, json::object());
  const json& plant = s["plant"];
  const double pipes = plant["pipes"], length = 40.0;
  REQUIRE(pipes == 26);
  // Each section's pipe walls: the heat that entered its ground through
  // them (negative: drawn), per metre of section, over the wedge's share of
  // the ring's walls; the weights by hand from the depths 12 and 32 m.
  const double w_top = 12.0 + (32.0 - 12.0) / 2.0;
  const double weights[] = {w_top, length - w_top};
  double ground = 0.0;
  for (std::size_t k = 0; k < 2; ++k) {
    const json& layer = s["layers"][k];
    const double share = pipes * layer["wedge"]["angle_deg"].get<double>() / 360.0;
    ground += -layer["heat_balance"]["from_boundaries"]["pipes"].get<double>() / share * weights[k] * pipes;
    CHECK(plant["sections"][k]["weight_m"].get<double>() == Approx(weights[k]).epsilon(1e-12));
    CHECK(layer["layer"]["brine_temperature"] == plant["sections"][k]["brine_temperature"]);
  }
  const double plant_heat = plant["heat_balance"]["plant_J"];
  fmt::print("\nShaft with its plant (5 cm, 60 d): plant {:.7e} J, sections' pipe walls {:.7e} J; peak {:.2f} kW on "
             "day {:.2f}; end {:.1f} kW, supply {:.2f} C, return {:.2f} C\n",
             plant_heat, ground, plant["peak_load_kw"].get<double>(), plant["peak_load_day"].get<double>(),
             plant["end_load_kw"].get<double>(), plant["end_supply_temperature"].get<double>(),
             plant["end_return_temperature"].get<double>());
  CHECK(plant_heat == Approx(ground).epsilon(1e-6));

  // The last row: load = pipes m c (return - supply), with the brine as
  // last taken, calcium chloride's at the mean of the row before it.
  const auto rows = plant_rows(dir.path / "out" / "plant.csv");
  // Hourly exchanges while the plant is held at its capacity, longer ones
  // (to 12 h) once its supply is at its coldest and the brine settles.
  REQUIRE(rows.size() > 2);
  CHECK(rows.back()[0] == Approx(60.0));
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double hours = 24.0 * (rows[k][0] - rows[k - 1][0]);
    CHECK(hours > 0.99);
    CHECK(hours < 12.01);
    if (rows[k][2] > -30.0 + 1e-9) CHECK(hours < 1.01);  // the supply that ran, chosen for the capacity
  }
  const json& last = plant["series"].back();
  const json& brine = plant["brine"];
  const double flow = 1.5 / 3600.0;
  CHECK(last["load_kw"].get<double>() * 1e3 ==
        Approx(pipes * brine["density"].get<double>() * brine["heat_capacity"].get<double>() * flow *
               (last["return_temperature"].get<double>() - last["supply_temperature"].get<double>()))
            .epsilon(1e-9));
  const auto& before = rows[rows.size() - 2];
  const auto cacl2 = frostwall::project::cacl2_brine(0.29, 0.5 * (before[2] + before[3]));
  CHECK(brine["density"].get<double>() == Approx(cacl2.density).epsilon(1e-6));
  CHECK(brine["heat_capacity"].get<double>() == Approx(cacl2.heat_capacity).epsilon(1e-6));
  CHECK(brine["viscosity"].get<double>() == Approx(cacl2.viscosity).epsilon(1e-5));

  // The capacity: never passed by more than the predictor's lag; the supply
  // starts well above its coldest and ends there; the clay's brine (deeper)
  // warmer than the sand's from the second exchange on.
  for (std::size_t k = 0; k < rows.size(); ++k) {
    CHECK(rows[k][1] < 120.0 * 1.01);
    if (k > 0) CHECK(rows[k][6] > rows[k][5]);
  }
  CHECK(rows.front()[2] > -25.0);
  CHECK(rows.back()[2] == Approx(-30.0));
  CHECK(plant["peak_load_kw"].get<double>() > 100.0);

  // Unlimited, at the coldest supply from the start: both close sooner.
  const json free = run_plant_shaft(
      free_dir.path,
      {{"plant", {{"capacity_kw", nullptr}, {"min_supply_temperature", nullptr}, {"supply_temperature", -30.0}}}});
  for (std::size_t k = 0; k < 2; ++k) {
    const double limited = s["layers"][k]["closure_time_days"], unlimited = free["layers"][k]["closure_time_days"];
    fmt::print("  {}: closure {:.3f} d at 120 kW, {:.3f} d unlimited\n",
               s["layers"][k]["layer"]["name"].get<std::string>(), limited, unlimited);
    CHECK(limited > unlimited);
  }
  fmt::print("  unlimited: peak {:.1f} kW on day {:.2f}\n", free["plant"]["peak_load_kw"].get<double>(),
             free["plant"]["peak_load_day"].get<double>());
  CHECK(free["plant"]["peak_load_kw"].get<double>() > 120.0);

  // The report leads with the plant's peak and shows the sizing; every
  // name of the plant's section is in its view.
  std::ifstream html_in(dir.path / "out" / "report.html");
  const std::string html((std::istreambuf_iterator<char>(html_in)), {});
  CHECK(html.find("Plant's peak load") != std::string::npos);
  CHECK(html.find("<h3>Sizing</h3>") != std::string::npos);
  const json view = frostwall::report::report_view(dir.path / "out");
  frostwall::test::check_section_filled(view, "has_plant");
  frostwall::test::check_section_filled(view, "plant_card");
}

TEST_CASE("One section with a plant at a flow too fast to warm the brine closes as with the brine held at the supply",
          "[plant]") {
  frostwall::test::TempDir plant_dir("plant_fast"), held_dir("plant_held");
  const json patch = {{"numerics", {{"spacing", 0.05}}},
                      {"time", {{"end", 25}, {"unit", "d"}, {"snapshots", {25}}}},
                      {"output", {{"vtk", false}, {"report", false}}}};
  json with_plant = patch;
  with_plant["pipe"] = frostwall::test::coaxial_pipe(40);
  with_plant["pipe"]["temperature"] = nullptr;
  with_plant["brine"] = {{"flow_per_pipe", 400}};
  with_plant["plant"] = {{"supply_temperature", -30}};
  frostwall::test::run_shipped("single_ring_sand.json", with_plant, plant_dir.path);
  const json s = read_json(plant_dir.path / "summary.json");
  const json& plant = s["plant"];
  CHECK(plant["sections"][0]["depth"].get<double>() == 20.0);
  // The film the plant's brine had, held: 1 / (pi d R_ground).
  const double h = 1.0 / (M_PI * 0.127 * plant["films"]["R_ground"].get<double>());
  json held = patch;
  held["pipe"] = {
      {"temperature", nullptr}, {"boundary", "brine"}, {"brine_temperature", -30.0}, {"heat_transfer_coefficient", h}};
  frostwall::test::run_shipped("single_ring_sand.json", held, held_dir.path);
  const double coupled = s["closure_time_days"], fixed = read_json(held_dir.path / "summary.json")["closure_time_days"];
  fmt::print("\nFast brine on one section: return {:.4f} C over a supply of -30 C, h = {:.0f} W/(m2 K); closure "
             "{:.4f} d with the plant, {:.4f} d held\n",
             plant["end_return_temperature"].get<double>(), h, coupled, fixed);
  CHECK(plant["end_difference_K"].get<double>() < 0.05);
  CHECK(coupled == Approx(fixed).epsilon(2e-3));
}

TEST_CASE("frostwall check tells the plant: pipes with flow, films, capacity, sections coupled",
          "[plant][cli][check]") {
  frostwall::test::TempDir dir("plant_check");
  const auto run = frostwall::test::frostwall_cli(
      dir.path, "check '" + (fs::path(FROSTWALL_SOURCE_DIR) / "projects" / "shaft_plant.json").string() + "'");
  REQUIRE(run.exit_status == 0);
  std::ifstream in(dir.path / "cli_stdout.txt");
  const std::string out((std::istreambuf_iterator<char>(in)), {});
  INFO(out);
  CHECK(out.find("plant: 26 pipes with flow, 1.5 m3/h each down the annulus") != std::string::npos);
  CHECK(out.find("120 kW, supply no colder than -30 C; 2 sections coupled through the brine") != std::string::npos);
}
