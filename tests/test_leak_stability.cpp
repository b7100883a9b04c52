// Story: the coupled grains and water stay stable, and a packing read from
// the cache continues as the one settled in the run.
//  - a scaled leak (8 mm grains over a kept cavity) at 0.3 m/s, five times
//    the packing's fluidisation velocity, runs 1 s: its kinetic energy stays
//    below what every grain would have after falling the box's height, and
//    every grain is counted in the soil or in the cavity at every output;
//  - the same packing settled in the run and read back from the cache (a
//    LAMMPS restart that keeps the contacts' springs) loses as many grains
//    as each other within the spread between two seeds;
//  - a drag held for far longer than its relaxation time m/K (explicit,
//    500 steps in a viscous fluid) grows without bound: the run stops with
//    one line naming the energy, the time and the cause, exit status 1, and
//    no summary; with the semi-implicit drag the same set-up stays bounded.
#include <catch2/catch.hpp>

#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// 2 200 quartz grains of 8 mm in a 0.1 m cube over a cavity of radius
// 2.5 cm whose crown is 1.5 cm under the surface, settled densely, then
// strong (friction 0.8, rolling resistance 0.5); flow along y at 0.3 m/s.
json scaled_leak(int seed, double end) {
  return {{"name", "leak at 0.3 m/s, scaled"},
          {"physics", "cfd-dem"},
          {"box", {{"low", {0, 0, 0}}, {"high", {0.1, 0.1, 0.1}}}},
          {"grains",
           {{"diameter", 0.008},
            {"density", 2650},
            {"count", 2200},
            {"youngs_modulus", 1e7},
            {"poisson_ratio", 0.3},
            {"restitution", 0.5},
            {"friction", 0.8},
            {"rolling_friction", 0.5},
            {"settle_friction", 0.1},
            {"seed", seed},
            {"settle_time", 0.4},
            {"fill", {{"low", {0, 0, 0}}, {"high", {0.1, 0.1, 0.18}}}}}},
          {"cavity", {{"centre", {0.05, 0.05, 0.06}}, {"radius", 0.025}}},
          {"point_a", {0.05, 0.05, 0.09}},
          {"fluid", {{"density", 1000}, {"viscosity", 0.001}, {"cell_size", 0.01}}},
          {"flow", {{"inflow", "y_min"}, {"darcy_velocity", 0.3}, {"outflow", "y_max"}}},
          {"time", {{"end", end}, {"unit", "s"}, {"snapshots", {0.5 * end, end}}}},
          {"output", {{"directory", "out"}, {"report", false}, {"vtk", false}}}};
}

struct Outcome {
  int status = -1;
  std::string said;
  json summary;
  bool summary_written = false, report_written = false;
};

// `frostwall run` on a project with its own packing cache.
Outcome run_with_cache(const json& project, const fs::path& cache) {
  frostwall::test::TempDir dir;
  std::ofstream(dir.path / "p.json") << project.dump(2);
  const auto run =
      frostwall::test::frostwall_cli(dir.path, "run p.json", {"env FROSTWALL_CACHE='" + cache.string() + "'", 0});
  Outcome o;
  o.status = run.exit_status;
  for (const auto& line : run.stderr_lines) o.said += line + "\n";
  o.summary_written = fs::exists(dir.path / "out" / "summary.json");
  o.report_written = fs::exists(dir.path / "out" / "report.html");
  if (o.status == 0 && o.summary_written) o.summary = json::parse(std::ifstream(dir.path / "out" / "summary.json"));
  return o;
}

double lost_at(const json& summary, double t) {
  for (const auto& row : summary["soil"]["series"])
    if (row["time"].get<double>() >= t - 1e-9) return row["lost_to_cavity"];
  return -1.0;
}

}  // namespace

TEST_CASE("leak, scaled: a cached packing continues as the settled one within the seed spread, and 0.3 m/s runs 1 s "
          "with bounded energy and every grain accounted for",
          "[cfd_dem][leak][stability][two_cores]") {
  frostwall::test::TempDir cache_1, cache_2;
  // Seeds 1 and 2 settled in the run, side by side (the machine's two cores).
  auto second = std::async(std::launch::async, run_with_cache, scaled_leak(2, 0.5), cache_2.path);
  const Outcome seed_1 = run_with_cache(scaled_leak(1, 0.5), cache_1.path);
  const Outcome seed_2 = second.get();
  INFO(seed_1.said << seed_2.said);
  REQUIRE(seed_1.status == 0);
  REQUIRE(seed_2.status == 0);
  // Seed 1 again from its cached packing, for 1 s.
  const Outcome cached = run_with_cache(scaled_leak(1, 1.0), cache_1.path);
  INFO(cached.said);
  REQUIRE(cached.status == 0);
  CHECK_FALSE(seed_1.summary["packing"]["read_from_cache"].get<bool>());
  CHECK(cached.summary["packing"]["read_from_cache"].get<bool>());

  const double settled = lost_at(seed_1.summary, 0.5), other_seed = lost_at(seed_2.summary, 0.5);
  const double from_cache = lost_at(cached.summary, 0.5);
  const double spread = std::abs(settled - other_seed);
  fmt::print("leak at 0.3 m/s, scaled: lost by 0.5 s {} (settled in the run), {} (from the cache), {} (seed 2)\n",
             settled, from_cache, other_seed);
  CHECK(settled > 0.0);
  CHECK(std::abs(from_cache - settled) <= std::max(spread, 1.0));

  // Bounded: below every grain's fall through the box (M g H), and the
  // guard's own measures stay under its limits.
  const json& s = cached.summary["stability"];
  const double mass = cached.summary["grains"].get<double>() * 2650.0 * M_PI / 6.0 * std::pow(0.008, 3);
  fmt::print("  1 s: peak kinetic energy {:.3g} J at {:.3g} s (M g H = {:.3g} J), fastest grain {:.3g} m/s\n",
             s["peak_kinetic_energy_J"].get<double>(), s["peak_kinetic_energy_at_s"].get<double>(), mass * 9.81 * 0.1,
             s["fastest_grain_m_s"].get<double>());
  CHECK(s["drag"] == "semi_implicit");
  // The chosen interval holds the forces for at most a fifth of the bed's
  // relaxation time rho_p / beta met at each update, and never longer than
  // its cap.
  CHECK_FALSE(s["interval_steps"]["given"].get<bool>());
  CHECK(s["held_over_bed_relaxation"].get<double>() <= 0.2 + 1e-9);
  CHECK(s["interval_steps"]["shortest"].get<int>() <= s["interval_steps"]["longest"].get<int>());
  fmt::print("  interval {}-{} steps, held at most {:.2f} of the bed's relaxation time ({:.3g} s) and {:.2f} of a "
             "grain's drag relaxation time\n",
             s["interval_steps"]["shortest"].get<int>(), s["interval_steps"]["longest"].get<int>(),
             s["held_over_bed_relaxation"].get<double>(), s["shortest_bed_relaxation_s"].get<double>(),
             s["held_over_drag_relaxation"].get<double>());
  CHECK(s["peak_kinetic_energy_J"].get<double>() < mass * 9.81 * 0.1);
  CHECK(s["fastest_grain_m_s"].get<double>() < 3.0 * s["speed_bound_m_s"].get<double>());
  CHECK(s["series"].size() > 100);
  const json& soil = cached.summary["soil"];
  const double start = soil["grains_at_start"];
  for (const auto& row : soil["series"]) {
    CHECK(row["grains_in_model"].get<double>() == start);
    CHECK(row["grains_in_soil"].get<double>() + row["lost_to_cavity"].get<double>() + row["washed_out"].get<double>() ==
          start);
  }
}

namespace {

// 200 grains of 6 mm settling in a fluid a thousand times as viscous as
// water: the drag's relaxation time m/K is about a millisecond.
json viscous_settling(const std::string& drag) {
  return {{"name", "viscous settling"},
          {"physics", "cfd-dem"},
          {"box", {{"low", {0, 0, 0}}, {"high", {0.06, 0.06, 0.12}}}},
          {"grains",
           {{"diameter", 0.006},
            {"density", 2650},
            {"count", 200},
            {"youngs_modulus", 1e7},
            {"poisson_ratio", 0.3},
            {"restitution", 0.5},
            {"friction", 0.5},
            {"seed", 1},
            {"settle_time", 0},
            {"fill", {{"low", {0, 0, 0.06}}, {"high", {0.06, 0.06, 0.12}}}}}},
          {"fluid", {{"density", 1000}, {"viscosity", 1.0}, {"cell_size", 0.01}}},
          {"coupling", {{"drag", drag}, {"interval", 500}}},
          {"time", {{"end", 1.0}, {"unit", "s"}, {"snapshots", {1.0}}}},
          {"output", {{"directory", "out"}, {"report", true}, {"vtk", false}}}};
}

}  // namespace

TEST_CASE(
    "cfd-dem: a drag held far beyond its relaxation time stops with the diagnosis, exit 1 and no summary, and the "
    "semi-implicit drag runs it",
    "[cfd_dem][stability]") {
  frostwall::test::TempDir cache;
  const Outcome held = run_with_cache(viscous_settling("explicit"), cache.path);
  INFO(held.said);
  CHECK(held.status == 1);
  CHECK_FALSE(held.summary_written);
  CHECK_FALSE(held.report_written);
  // One line: the instability, its energy and time, the cause and the remedy.
  CHECK(held.said.find("unstable at t =") != std::string::npos);
  CHECK(held.said.find("kinetic energy") != std::string::npos);
  CHECK(held.said.find("relaxation time") != std::string::npos);
  CHECK(held.said.find("\"coupling.drag\": \"semi_implicit\"") != std::string::npos);

  const Outcome semi = run_with_cache(viscous_settling("semi_implicit"), cache.path);
  INFO(semi.said);
  REQUIRE(semi.status == 0);
  const json& s = semi.summary["stability"];
  // Held 500 steps, many relaxation times, and still bounded: no grain
  // moves as fast as a free fall through the grains' 6 cm column would
  // make it (the held pressure gradient and water velocity still lag, so
  // the grains overshoot Stokes' terminal velocity: the chosen interval,
  // not this one, is the accurate one).
  CHECK(s["held_over_drag_relaxation"].get<double>() > 5.0);
  const double stokes = (2650.0 - 1000.0) * 9.81 * 0.006 * 0.006 / 18.0;  // m/s, Re well below 1
  fmt::print("viscous settling: held {:.1f} relaxation times; fastest grain {:.3g} m/s (Stokes {:.3g} m/s)\n",
             s["held_over_drag_relaxation"].get<double>(), s["fastest_grain_m_s"].get<double>(), stokes);
  CHECK(s["fastest_grain_m_s"].get<double>() < std::sqrt(2.0 * 9.81 * 0.06));
}
