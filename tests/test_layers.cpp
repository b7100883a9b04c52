// A shaft through layers: one cross-section per layer, run side by side.
// Each layer's results must be those of the same project run alone
// with that layer's soil, depth, pressure and strength; the governing layer
// is the one met last; the report leads with its verdict.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "report/mustache_view.hpp"
#include "report/report.hpp"
#include "report/report_sections.hpp"
#include "report/templates.hpp"
#include "report_view_check.hpp"
#include "cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json scaled_shaft() {
  return {
      {"name", "scaled shaft"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 0.8}, {"count", 6}, {"start_angle_deg", 0.0}}}}},
      {"shaft", {{"excavation_radius", 0.5}}},
      {"pipe",
       {{"diameter", 0.127}, {"boundary", "brine"}, {"brine_temperature", -25.0}, {"heat_transfer_coefficient", 300}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 2.5}, {"initial_temperature", 10.0}, {"far_field", {{"temperature", 10.0}}}}},
      {"time", {{"end", 12}, {"unit", "d"}, {"snapshots", {4, 8, 12}}}},
      {"numerics", {{"placement", "lattice"}, {"spacing", 0.05}}},
      {"design", {{"strength", {{"a", 1.0}, {"b", 0.3}}}, {"pressure", {{"gradient_MPa_per_m", 0.013}}}}},
      {"output", {{"directory", "out"}, {"vtk", false}, {"report", true}}}};
}

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Every number of two JSON values alike (to a relative 1e-12), every other value equal.
void same_numbers(const json& a, const json& b, const std::string& where) {
  INFO(where);
  REQUIRE(a.type() == b.type());
  if (a.is_number()) {
    CHECK(a.get<double>() == Approx(b.get<double>()).epsilon(1e-12).margin(1e-14));
  } else if (a.is_array()) {
    REQUIRE(a.size() == b.size());
    for (std::size_t k = 0; k < a.size(); ++k) same_numbers(a[k], b[k], where + fmt::format("[{}]", k));
  } else if (a.is_object()) {
    for (const auto& [key, value] : a.items()) {
      REQUIRE(b.contains(key));
      same_numbers(value, b[key], where + "." + key);
    }
  } else {
    CHECK(a == b);
  }
}

}  // namespace

TEST_CASE("Layers: a two-layer shaft gives each layer the results of its own run, and the deeper clay governs",
          "[freezing][design][layers][cli]") {
  json layered = scaled_shaft();
  layered["layers"] = {
      {{"name", "sand 60 m"}, {"depth", 60}},
      {{"name", "clay 120 m"}, {"depth", 120}, {"soil", "clay"}, {"strength", {{"a", 0.8}, {"b", 0.25}}}}};
  std::string report;
  std::vector<bool> layer_reports;
  const json top = frostwall::test::run_project(layered, [&](const fs::path& out) {
    report = read(out / "report.html");
    // Every name of the wall check's and the brine's sections is in the view.
    const json view = frostwall::report::report_view(out);
    CHECK(view["has_wall_check"] == true);
    CHECK(view["has_layers"] == true);
    CHECK(view["has_brine"] == true);
    for (const char* section : {"has_wall_check", "has_brine"})
      for (const auto& name : frostwall::report::template_names(
               frostwall::test::split_section(frostwall::report::templates::report_html, section).first)) {
        INFO(name);
        CHECK(frostwall::test::has_key(view, name));
      }
    for (const char* folder : {"sand_60_m", "clay_120_m"})
      layer_reports.push_back(fs::exists(out / folder / "report.html"));
  });
  CHECK(layer_reports == std::vector<bool>{true, true});

  // The same two cross-sections as projects of their own.
  json sand = scaled_shaft();
  sand["design"]["depth"] = 60;
  json clay = scaled_shaft();
  clay["soil"] = "clay";
  clay["design"]["depth"] = 120;
  clay["design"]["strength"] = {{"a", 0.8}, {"b", 0.25}};
  const json alone[2] = {frostwall::test::run_project(sand, {}, "--threads 1"),
                         frostwall::test::run_project(clay, {}, "--threads 1")};
  REQUIRE(top["layers"].size() == 2);
  for (int k = 0; k < 2; ++k) {
    const json& l = top["layers"][k];
    for (const char* key : {"closure_time_days", "front_contact_days", "wall", "design"})
      same_numbers(l[key], alone[k][key], fmt::format("layers[{}].{}", k, key));
  }
  CHECK(top["layers"][0]["design"]["pressure_MPa"].get<double>() == Approx(0.013 * 60).epsilon(1e-12));
  CHECK(top["layers"][1]["design"]["pressure_MPa"].get<double>() == Approx(0.013 * 120).epsilon(1e-12));
  CHECK(top["layers"][1]["layer"]["soil"] == "clay");

  // Weaker clay under twice the pressure is met later: it governs, and the
  // layered summary is its summary.
  const auto met = [](const json& s) {
    return s["design"]["met_day"].is_number() ? s["design"]["met_day"].get<double>() : 1e9;
  };
  CHECK(met(alone[1]) > met(alone[0]));
  CHECK(top["governing_layer"] == "clay 120 m");
  CHECK(top["layers"][1]["layer"]["governing"] == true);
  same_numbers(top["wall"], alone[1]["wall"], "wall");
  // The report's headline names the governing layer's verdict.
  const std::string headline = alone[1]["design"]["met_day"].is_number()
                                   ? fmt::format("design met on day {:.0f} in clay 120 m at 120 m", met(alone[1]))
                                   : std::string("design not met by day 12 in clay 120 m at 120 m");
  CHECK(report.find(headline) != std::string::npos);
  CHECK(report.find("id=\"wall-check\"") != std::string::npos);
  WARN(fmt::format("met: sand at 60 m day {}, clay at 120 m day {}", alone[0]["design"]["met_day"].dump(),
                   alone[1]["design"]["met_day"].dump()));
}

TEST_CASE("The design verdict says when a wall that passed fails again", "[freezing][design][report]") {
  json s = {{"design", {{"met_day", 40.0}, {"stays_met", false}}}, {"wall", {{{"day", 120.0}, {"utilisation", 1.2}}}}};
  CHECK(frostwall::report::detail::design_verdict(s) ==
        "design met on day 40 (but not for good: it fails again later); utilisation 1.20 on day 120");
  s["design"]["stays_met"] = true;
  s["wall"][0]["utilisation"] = 0.93;
  CHECK(frostwall::report::detail::design_verdict(s) == "design met on day 40; utilisation 0.93 on day 120");
  s["design"]["met_day"] = nullptr;
  CHECK(frostwall::report::detail::design_verdict(s) == "design not met by day 120; utilisation 0.93 on day 120");
}
