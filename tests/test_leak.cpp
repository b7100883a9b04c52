// Story: seepage erosion over a cavity (issue 16), on a scaled case that
// runs in about a minute: a 0.1 m cube of 6 mm quartz grains in water over
// an unlined spherical cavity (radius 2.5 cm, crown 2 cm under the
// surface), settled densely once (low friction while settling) and shared
// by every run through the packing cache:
//  - with no flow, a strong packing (rolling resistance 0.5) stays put:
//    under 1 % of its grains move more than a diameter or fall in;
//  - with flow along y, the grains lost rise with the Darcy velocity over
//    0.01, 0.2 and 0.3 m/s (21, 75, 590 of 4 616 here); they leave only into the cavity (the outflow
//    face is a screen), and soil plus lost is the starting count;
//  - a weak packing (rolling resistance 0.1) caves in under gravity alone:
//    the zone above the cavity empties (porosity 1) and the surface settles
//    most above the cavity.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "temp_dir.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json scaled_case(double rolling, double velocity) {
  json p = {
      {"name", "leak over a cavity, scaled"},
      {"physics", "cfd-dem"},
      {"box", {{"low", {0, 0, 0}}, {"high", {0.1, 0.1, 0.1}}}},
      {"grains",
       {{"diameter", 0.006}, {"density", 2650}, {"count", 5000}, {"youngs_modulus", 1e7}, {"poisson_ratio", 0.3},
        {"restitution", 0.5}, {"friction", 0.8}, {"rolling_friction", rolling}, {"settle_friction", 0.1},
        {"seed", 1}, {"settle_time", 0.4}, {"fill", {{"low", {0, 0, 0}}, {"high", {0.1, 0.1, 0.18}}}}}},
      {"cavity", {{"centre", {0.05, 0.05, 0.06}}, {"radius", 0.025}}},
      {"point_a", {0.05, 0.05, 0.09}},
      {"fluid", {{"density", 1000}, {"viscosity", 0.001}, {"cell_size", 0.01}}},
      {"time", {{"end", 0.3}, {"unit", "s"}, {"snapshots", {0.15, 0.3}}}},
      {"output", {{"directory", "out"}, {"report", false}, {"vtk", false}}}};
  if (velocity > 0) p["flow"] = {{"inflow", "y_min"}, {"darcy_velocity", velocity}, {"outflow", "y_max"}};
  return p;
}

// One cache for the whole test run: the settled packings are shared.
const fs::path& cache() {
  static frostwall::test::TempDir dir("frostwall-leak-cache");
  return dir.path;
}

json run(const json& project) {
  frostwall::test::TempDir dir;
  std::ofstream(dir.path / "p.json") << project.dump(2);
  setenv("FROSTWALL_CACHE", cache().c_str(), 1);
  const std::string command = "cd '" + dir.path.string() + "' && '" FROSTWALL_EXE "' run p.json > log.txt 2>&1";
  const int status = std::system(command.c_str());
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  std::ifstream in(dir.path / "out" / "summary.json");
  return json::parse(in)["soil"];
}

void check_conserved(const json& soil) {
  for (const auto& row : soil["series"])
    CHECK(row["grains_in_soil"].get<double>() + row["lost_to_cavity"].get<double>() + row["washed_out"].get<double>() ==
          soil["grains_at_start"].get<double>());
}

}  // namespace

TEST_CASE("leak, scaled: a strong packing stands without flow, and flow carries grains into the cavity", "[cfd_dem][leak]") {
  const json still = run(scaled_case(0.5, 0.0));
  const double start = still["grains_at_start"];
  const auto& end = still["series"].back();
  const double moved = end["moved_one_diameter"].get<double>() + end["lost_to_cavity"].get<double>();
  fmt::print("leak, no flow: {} grains, {} fell in, {} moved more than a diameter\n", start,
             end["lost_to_cavity"].get<double>(), end["moved_one_diameter"].get<double>());
  CHECK(moved < 0.01 * start);
  check_conserved(still);

  double previous = -1.0;
  double first = 0.0;
  for (double u : {0.01, 0.2, 0.3}) {
    const json soil = run(scaled_case(0.5, u));
    const double lost = soil["lost_to_cavity"].get<double>() + soil["washed_out"].get<double>();
    fmt::print("leak, {} m/s: {} grains lost ({} into the cavity, {} washed out); {}\n", u, lost,
               soil["lost_to_cavity"].get<double>(), soil["washed_out"].get<double>(),
               soil["regime"]["note"].get<std::string>());
    CHECK(soil["grains_at_start"] == start);  // the same cached packing
    CHECK(lost > previous);
    CHECK(soil["washed_out"] == 0);  // the outflow face is a screen: the cavity is the only way out
    check_conserved(soil);
    if (u == 0.01) first = lost;
    previous = lost;
  }
  CHECK(previous > 5.0 * first);  // far above fluidisation the flow, not gravity, empties the crown
}

TEST_CASE("leak, scaled: a weak packing caves in over the cavity and the surface settles most above it", "[cfd_dem][leak]") {
  const json soil = run(scaled_case(0.1, 0.0));
  check_conserved(soil);
  const auto& end = soil["series"].back();
  fmt::print("leak, weak packing: {} fell in, zone porosity {:.3f} -> {:.3f}, settlement {:.1f} mm over {:.0f} mm\n",
             end["lost_to_cavity"].get<double>(), soil["series"][0]["zone_porosity"].get<double>(),
             end["zone_porosity"].get<double>(), 1e3 * end["settlement_max_m"].get<double>(),
             1e3 * end["settlement_width_m"].get<double>());
  // Once the grains over the crown are gone, the zone is empty.
  CHECK(end["zone_porosity"].get<double>() == Approx(1.0).margin(0.02));
  // The deepest settlement lies over the cavity (x within its radius).
  const auto& profile = soil["surface_profiles"].back()["settlement"];
  double deepest = -1.0, at = 0.0;
  for (const auto& bin : profile)
    if (bin[1].get<double>() > deepest) deepest = bin[1].get<double>(), at = bin[0].get<double>();
  CHECK(std::abs(at - 0.05) < 0.025);
  CHECK(deepest == Approx(end["settlement_max_m"].get<double>()));
  CHECK(deepest > 0.006);  // more than a grain
}
