// Story: a heat run marched in parts (freezing::SteppedHeatRun), stopped at
// its own snapshot days, steps exactly as the run in one go: the single
// ring, scaled (5 cm, 20 days), gives the same summary numbers to the last
// digit (closure, wall, heat balance), and stops between snapshots are
// landed on.
#include <catch2/catch.hpp>

#include <fstream>
#include <nlohmann/json.hpp>

#include "freezing/heat_run.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"

using namespace frostwall;

namespace {

project::Project scaled_ring(const std::filesystem::path& out) {
  return test::shipped_project("single_ring_sand.json",
                               {{"numerics", {{"spacing", 0.05}, {"error_estimate", false}}},
                                {"time", {{"end", 20}, {"unit", "d"}, {"snapshots", {10, 20}}}},
                                {"output", {{"vtk", false}, {"report", false}}}},
                               out);
}

nlohmann::json summary_of(const std::filesystem::path& out) {
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("A heat run marched in parts steps as the run in one go", "[freezing][summary][stepped]") {
  test::TempDir one("stepped_one"), parts("stepped_parts");
  const auto p1 = scaled_ring(one.path);
  auto m1 = freezing::build_model(p1);
  freezing::run_heat(p1, m1, {});

  const auto p2 = scaled_ring(parts.path);
  auto m2 = freezing::build_model(p2);
  freezing::SteppedHeatRun run(p2, m2, {});
  CHECK(run.advance_to(10 * 86400.0) == 10 * 86400.0);
  CHECK_FALSE(run.done());
  CHECK(run.advance_to(1e12) == 20 * 86400.0);
  CHECK(run.done());
  run.finish();

  const auto a = summary_of(one.path), b = summary_of(parts.path);
  REQUIRE(a["closure_time_days"].is_number());
  CHECK(b["closure_time_days"] == a["closure_time_days"]);
  CHECK(b["heat_balance"] == a["heat_balance"]);
  CHECK(b["run"]["steps"] == a["run"]["steps"]);
}
