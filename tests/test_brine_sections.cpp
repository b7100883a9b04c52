// Story: the single ring in sand (scaled: 5 cm, 20 days) at two depths of
// a 30 m coaxial freeze pipe (127 mm steel, 63 mm polyethylene supply
// pipe), 26 pipes on the plant, brine supplied at -30 C down the annulus.
// References:
//  - energy: the plant's heat over the run (the loads over their
//    intervals) equals the heat the sections' ground lost through the pipe
//    walls, from each section's own heat balance (stored change less the
//    far field's heat), integrated along the pipe with the sections'
//    weights, within 1e-6;
//  - every row: the load is n m c (T_return - T_supply), the return warmer;
//  - the constant-brine limit: at a flow too fast for the brine to warm,
//    each section closes within 0.2 % of the run with the brine held at the
//    supply behind the same film;
//  - at 1.5 m3/h the brine warms on its way down, so the deeper section
//    sees warmer brine and closes later.
#include <catch2/catch.hpp>

#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "freezing/brine_sections.hpp"
#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"

using namespace frostwall;

namespace {

project::Project ring(const std::filesystem::path& out) {
  return test::shipped_project("single_ring_sand.json",
                               {{"numerics", {{"spacing", 0.05}, {"error_estimate", false}}},
                                {"time", {{"end", 20}, {"unit", "d"}, {"snapshots", {20}}}},
                                {"output", {{"vtk", false}, {"report", false}}}},
                               out);
}

freezing::CircuitSettings circuit(double flow_m3_per_h) {
  freezing::CircuitSettings s;
  s.pipe = {0.127, 0.0063, 50.0, 0.063, 0.0058, 0.4, 30.0};
  s.brine = {1290.0, 0.0098, 0.52, 2700.0};
  s.flow = flow_m3_per_h / 3600.0;
  s.supply = project::TemperatureSchedule::fixed(-30.0);
  s.pipes = 26;
  s.interval = 0.05 * 86400.0;
  return s;
}

struct Circuit {
  test::TempDir top{"circuit_top"}, deep{"circuit_deep"};
  freezing::CircuitRun run;
  explicit Circuit(double flow) {
    run = freezing::run_brine_circuit({{ring(top.path), 5.0}, {ring(deep.path), 25.0}}, circuit(flow), {});
  }
};

double closure(const summary::Summary& s) { return summary::to_json(s).at("closure_time_days").get<double>(); }

}  // namespace

TEST_CASE("Sections coupled through the brine: energy, rows, and the deeper section's warmer brine",
          "[freezing][brine][circuit]") {
  Circuit c(1.5);
  const auto& r = c.run;
  double lost = 0.0;  // through the pipe walls, all pipes along the pipe
  for (std::size_t k = 0; k < 2; ++k) {
    const auto balance = summary::to_json(r.sections[k]).at("heat_balance");
    const double through_pipes = balance.at("stored_change").get<double>() -
                                 balance.at("from_boundaries").at("far_field").get<double>();
    // The section's share of pipes: the wedge holds whole pipes' worth of wall (a ring of 26, so 1 in 1/52).
    lost += -through_pipes / 0.5 * r.weights[k] * 26;
  }
  fmt::print(
      "\nBrine circuit: plant {:.6e} J, ground through the pipes {:.6e} J; closure top {:.3f} d, deep {:.3f} d\n",
      r.plant_heat, lost, closure(r.sections[0]), closure(r.sections[1]));
  CHECK(r.plant_heat == Approx(lost).epsilon(1e-6));
  CHECK(r.plant_heat == Approx(r.ground_heat).epsilon(1e-12));
  const double W = 1290.0 * 2700.0 * 1.5 / 3600.0;
  for (const auto& row : r.series) {
    CHECK(row.load == Approx(26 * W * (row.return_temperature - row.supply)).epsilon(1e-9));
    CHECK(row.return_temperature > row.supply);
    // Warmer down the annulus, from the second interval (the first runs at the supply).
    if (&row != &r.series.front()) CHECK(row.brine[1] > row.brine[0]);
  }
  CHECK(closure(r.sections[1]) > closure(r.sections[0]));
}

TEST_CASE("Sections coupled through fast brine close as with the brine held at the supply",
          "[freezing][brine][circuit]") {
  const double flow = 400.0;  // m3/h: the brine warms by about a hundredth of a kelvin
  Circuit c(flow);
  const auto s = circuit(flow);
  const auto r = design::coaxial_resistances(s.pipe, s.brine, s.flow);
  test::TempDir held_dir("circuit_held");
  auto p = ring(held_dir.path);
  auto& pipe = std::get<project::ShaftSection>(p.geometry).pipe;
  pipe.boundary = project::PipeBoundary::brine;
  pipe.heat_transfer_coefficient = 1.0 / (M_PI * s.pipe.outer_diameter * r.ground);
  pipe.temperature = project::TemperatureSchedule::fixed(-30.0);
  auto m = freezing::build_model(p);
  const double held = closure(freezing::run_heat(p, m, {}));
  const auto& last = c.run.series.back();
  fmt::print(
      "\nFast brine ({} m3/h, h = {:.0f} W/(m2 K)): return {:.4f} C; closure {:.4f} / {:.4f} d against {:.4f} d held\n",
      flow, pipe.heat_transfer_coefficient, last.return_temperature, closure(c.run.sections[0]),
      closure(c.run.sections[1]), held);
  CHECK(last.return_temperature - last.supply < 0.1);
  for (const auto& section : c.run.sections) CHECK(closure(section) == Approx(held).epsilon(2e-3));
}

TEST_CASE("A plant at its capacity: the supply falls to its coldest, the load stays within the capacity",
          "[freezing][brine][circuit]") {
  // 26 pipes at 1.5 m3/h drawing up to 150 kW: at start-up the warm ground
  // would take more at -30 C, so the supply sits higher and falls as the
  // ground cools, to -30 C, where the load falls below the capacity. The
  // wall closes later than with an unlimited plant at -30 C.
  test::TempDir top("capacity_top"), deep("capacity_deep");
  auto s = circuit(1.5);
  s.capacity = 150e3;
  s.min_supply = -30.0;
  const auto limited = freezing::run_brine_circuit({{ring(top.path), 5.0}, {ring(deep.path), 25.0}}, s, {});
  Circuit unlimited(1.5);
  const auto& rows = limited.series;
  double peak = 0.0;
  std::size_t first_at_min = rows.size();
  for (std::size_t k = 0; k < rows.size(); ++k) {
    peak = std::max(peak, rows[k].load);
    if (rows[k].supply <= -30.0 && first_at_min == rows.size()) first_at_min = k;
    if (k > 0) CHECK(rows[k].supply <= rows[k - 1].supply + 0.01);  // falling (the predictor wobbles by mK)
  }
  fmt::print("\nPlant at 150 kW: supply {:.2f} C on day {:.2f}, at -30 C from day {:.2f}; peak load {:.1f} kW; "
             "closure {:.3f} / {:.3f} d against {:.3f} / {:.3f} d unlimited\n",
             rows.front().supply, rows.front().time / 86400,
             first_at_min < rows.size() ? rows[first_at_min].time / 86400 : -1.0, peak / 1e3,
             closure(limited.sections[0]), closure(limited.sections[1]), closure(unlimited.run.sections[0]),
             closure(unlimited.run.sections[1]));
  CHECK(rows.front().supply > -25.0);
  REQUIRE(first_at_min < rows.size());
  CHECK(rows.back().load < 150e3);
  CHECK(peak < 150e3 * 1.01);
  CHECK(limited.plant_heat == Approx(limited.ground_heat).epsilon(1e-12));
  for (std::size_t k = 0; k < 2; ++k) CHECK(closure(limited.sections[k]) > closure(unlimited.run.sections[k]));
}

TEST_CASE("Warm sand over clay: the clay sees brine warmed by the sand and closes as that brine says",
          "[freezing][brine][circuit]") {
  // The sand at 5 m and the clay at 25 m of the pipe (both single rings,
  // scaled). The clay closes later than with the brine held at the supply;
  // held instead at the brine the circuit gave it (step by step in time), it
  // closes on the same day: the delay is the warmer brine's, nothing else.
  test::TempDir sand_dir("warm_sand"), clay_dir("warm_clay"), held_dir("clay_held"), cold_dir("clay_cold");
  auto clay = [](const std::filesystem::path& out) {
    return test::shipped_project("single_ring_clay.json",
                                 {{"numerics", {{"spacing", 0.05}, {"error_estimate", false}}},
                                  {"time", {{"end", 25}, {"unit", "d"}, {"snapshots", {25}}}},
                                  {"output", {{"vtk", false}, {"report", false}}}},
                                 out);
  };
  auto sand = ring(sand_dir.path);
  sand.time = clay(sand_dir.path).time;
  const auto s = circuit(1.5);
  const auto run = freezing::run_brine_circuit({{sand, 5.0}, {clay(clay_dir.path), 25.0}}, s, {});
  const auto r = design::coaxial_resistances(s.pipe, s.brine, s.flow);
  auto held_at = [&](const std::filesystem::path& out, project::TemperatureSchedule brine) {
    auto p = clay(out);
    auto& pipe = std::get<project::ShaftSection>(p.geometry).pipe;
    pipe.boundary = project::PipeBoundary::brine;
    pipe.heat_transfer_coefficient = 1.0 / (M_PI * s.pipe.outer_diameter * r.ground);
    pipe.temperature = std::move(brine);
    auto m = freezing::build_model(p);
    return closure(freezing::run_heat(p, m, {}));
  };
  project::TemperatureSchedule seen;  // each interval's brine, held over it
  double before = 0.0;
  for (const auto& row : run.series) {
    seen.points.push_back({before, row.brine[1]});
    seen.points.push_back({row.time - 1.0, row.brine[1]});
    before = row.time;
  }
  const double coupled = closure(run.sections[1]), replayed = held_at(held_dir.path, seen),
               cold = held_at(cold_dir.path, project::TemperatureSchedule::fixed(-30.0));
  fmt::print("\nWarm sand over clay: the clay's brine {:.2f} C on day 1, {:.2f} C on day 15; closure {:.3f} d coupled, "
             "{:.3f} d held at that brine, {:.3f} d at the supply\n",
             run.series[19].brine[1], run.series[299].brine[1], coupled, replayed, cold);
  CHECK(coupled > cold);
  CHECK(coupled == Approx(replayed).epsilon(2e-3));
}
