// Brine pipes: a Robin condition at the pipe wall, q = h (T_wall -
// T_brine). Checked against the exact steady solution round one pipe (a
// film and a conducting annulus in series), against the fixed-temperature
// run as h grows, and for the heat it takes out: the film law integrated
// over the run against the heat the ground lost through the pipe walls.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli.hpp"

using nlohmann::json;

namespace {

json scaled_ring(const json& pipe) {
  return {
      {"name", "scaled ring, brine pipes"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 0.8}, {"count", 6}, {"start_angle_deg", 0.0}}}}},
      {"pipe", pipe},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 2.5}, {"initial_temperature", 10.0}, {"far_field", {{"temperature", 10.0}}}}},
      {"time", {{"end", 12}, {"unit", "d"}, {"snapshots", {6, 12}}}},
      {"numerics", {{"placement", "lattice"}, {"spacing", 0.05}}},
      {"output", {{"directory", "out"}, {"vtk", false}, {"report", false}}}};
}

json brine(double h) {
  return {{"diameter", 0.127}, {"boundary", "brine"}, {"brine_temperature", -20.0}, {"heat_transfer_coefficient", h}};
}

double heat_from_boundaries(const json& s) {
  double sum = 0.0;
  for (const auto& [name, q] : s["heat_balance"]["from_boundaries"].items()) sum += q.get<double>();
  return sum;
}

}  // namespace

TEST_CASE("Brine pipe at steady state round one pipe: wall temperature and heat per metre against the exact solution",
          "[freezing][brine][cli]") {
  // One pipe in a disc of radius R held at T_far, no latent heat and one
  // conductivity k: at steady state the film and the annulus carry the same
  // heat, h 2 pi r (T_w - T_b) = 2 pi k (T_far - T_w) / ln(R / r).
  const double r = 0.0635, R = 1.0, k = 2.0, h = 50.0, Tb = -20.0, Tfar = 10.0;
  const json soil = {{"name", "conductor"},
                     {"density", 2000},
                     {"unfrozen", {{"conductivity", k}, {"heat_capacity", 500}}},
                     {"frozen", {{"conductivity", k}, {"heat_capacity", 500}}},
                     {"latent_heat", 0.0}};
  auto steady = [&](double spacing) {
    json p = {{"name", "one brine pipe"},
              {"layout", {{"pattern", "pipes"}, {"pipes", {{{"x", 0.0}, {"y", 0.0}}}}}},
              {"pipe", brine(h)},
              {"soil", soil},
              {"domain", {{"outer_radius", R}, {"initial_temperature", Tfar}, {"far_field", {{"temperature", Tfar}}}}},
              {"time", {{"end", 30}, {"unit", "d"}, {"snapshots", {30}}}},
              {"numerics", {{"placement", "lattice"}, {"spacing", spacing}}},
              {"output", {{"directory", "out"}, {"vtk", false}, {"report", false}}}};
    p["pipe"]["diameter"] = 2 * r;
    return frostwall::test::run_project(p);
  };
  const double G = k / std::log(R / r);  // the annulus' conductance per 2 pi
  const double Tw = (G * Tfar + h * r * Tb) / (G + h * r);
  const double q = 2 * M_PI * h * r * (Tw - Tb);
  std::vector<double> wall_error, heat_error;
  for (double spacing : {0.02, 0.01}) {
    const json s = steady(spacing);
    const auto& last = s["brine"]["series"].back();
    wall_error.push_back(std::abs(last[1].get<double>() - Tw) / (Tfar - Tb));
    heat_error.push_back(std::abs(last[2].get<double>() - q) / q);
    WARN(fmt::format("spacing {}: wall {:.4f} degC (exact {:.4f}), {:.3f} W/m (exact {:.3f})", spacing,
                     last[1].get<double>(), Tw, last[2].get<double>(), q));
  }
  CHECK(wall_error.back() < 1e-3);  // of the brine-to-far-field difference
  CHECK(heat_error.back() < 5e-3);
  CHECK(wall_error.back() < 0.5 * wall_error.front());  // and it converges as the spacing halves
  CHECK(heat_error.back() < 0.5 * heat_error.front());
}

TEST_CASE(
    "Brine pipes on a scaled ring: h to infinity is the fixed wall, a finite film closes later, the heat balances",
    "[freezing][brine][cli]") {
  json fixed_pipe = {{"diameter", 0.127}, {"temperature", -20.0}};
  const json fixed = frostwall::test::run_project(scaled_ring(fixed_pipe));
  const json stiff = frostwall::test::run_project(scaled_ring(brine(1e6)));
  const json laminar = frostwall::test::run_project(scaled_ring(brine(100.0)));
  REQUIRE(fixed["closure_time_days"].is_number());
  REQUIRE(stiff["closure_time_days"].is_number());
  const double c_fixed = fixed["closure_time_days"].get<double>(), c_stiff = stiff["closure_time_days"].get<double>();
  CHECK(std::abs(c_stiff - c_fixed) / c_fixed < 0.005);
  // A finite film: the wall runs warmer than the brine, the ground freezes later.
  const double c_laminar = laminar["closure_time_days"].is_number() ? laminar["closure_time_days"].get<double>() : 1e9;
  CHECK(c_laminar > c_fixed);
  for (const auto& row : laminar["brine"]["series"]) {
    CHECK(row[1].get<double>() > -20.0);
    CHECK(row[1].get<double>() < 10.0);
    CHECK(row[2].get<double>() > 0.0);  // heat extracted: into the brine
  }
  for (const auto& row : stiff["brine"]["series"]) CHECK(std::abs(row[1].get<double>() + 20.0) < 0.01);
  WARN(fmt::format(
      "closure: fixed wall {:.3f} d, h = 1e6 {:.3f} d, h = 100 {:.3f} d; h = 100 wall {:.2f} degC on day {}", c_fixed,
      c_stiff, c_laminar, laminar["brine"]["series"].back()[1].get<double>(),
      laminar["brine"]["series"].back()[0].get<double>()));
  for (const json* s : {&stiff, &laminar}) {
    // Energy: the ground's stored heat changes by what crosses the walls;
    // what crosses the pipe walls is what the film law passes to the brine.
    const auto& hb = (*s)["heat_balance"];
    const double stored = hb["stored_change"].get<double>(),
                 through_pipes = hb["from_boundaries"]["pipes"].get<double>();
    CHECK(std::abs(stored - heat_from_boundaries(*s)) < 1e-6 * std::abs(stored));
    CHECK((*s)["brine"]["extracted_by_film"].get<double>() == Approx(-through_pipes).epsilon(0.01));
  }
}
