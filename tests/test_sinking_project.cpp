// The shipped sinking shaft (projects/shaft_sinking.json: the shaft with
// its plant, sand at 12 m over clay at 32 m, sunk from day 35 at 1 m a day,
// lined three days behind), scaled, run as `frostwall run` runs it.
// References: each layer is dug on day 35 + depth / rate (by hand) and
// lined three days later; every layer's heat balance closes (the pipes,
// the far field, the face, the ground taken out, the lining and its
// hydration against the stored change, 1e-6); the shaft's critical section
// is the layer with the smallest margin among the layers' own, on its day;
// each layer's excavation.csv has a row per entry of its series; the
// report names the critical section in its first lines and fills its
// sinking section. An as-built shaft's listed depths are each dug on the
// day given for them, and its critical section is theirs with the
// smallest margin.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "report/report.hpp"
#include "report_view_check.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

TEST_CASE("The shipped sinking shaft: each layer dug on its day, the critical section the smallest margin",
          "[excavation][shipped]") {
  frostwall::test::TempDir dir("shaft_sinking");
  std::ifstream in(fs::path(FROSTWALL_SOURCE_DIR) / "projects" / "shaft_sinking.json");
  json j = json::parse(in);
  j.merge_patch({{"numerics", {{"spacing", 0.05}}},
                 {"time", {{"end", 80}, {"unit", "d"}, {"snapshots", {40, 60, 80}}}},
                 {"output", {{"directory", "out"}, {"vtk", true}, {"full_ring", false}, {"report", true}}}});
  std::ofstream(dir.path / "project.json") << j.dump(2);
  const auto run = frostwall::test::frostwall_cli(dir.path, "run project.json");
  REQUIRE(run.exit_status == 0);
  std::ifstream summary_in(dir.path / "out" / "summary.json");
  const json s = json::parse(summary_in);

  const json& e = s["excavation"];
  double smallest = 1e300;
  std::string critical;
  for (const auto& layer : s["layers"]) {
    const json& x = layer["excavation"];
    const double depth = layer["layer"]["depth"];
    CHECK(x["day"].get<double>() == Approx(35.0 + depth / 1.0));
    CHECK(x["lining_day"].get<double>() == Approx(38.0 + depth / 1.0));
    REQUIRE(x["margin_min"].is_number());
    CHECK(x["margin_min_day"].get<double>() >= x["day"].get<double>());
    if (x["margin_min"].get<double>() < smallest)
      smallest = x["margin_min"], critical = layer["layer"]["name"].get<std::string>();
    double total = 0.0;
    for (const auto& [name, q] : layer["heat_balance"]["from_boundaries"].items()) total += q.get<double>();
    const double stored = layer["heat_balance"]["stored_change"];
    CHECK(std::abs(total - stored) <= 1e-6 * std::abs(stored));
    CHECK(layer["heat_balance"]["from_boundaries"]["hydration"].get<double>() > 0.0);
    // excavation.csv: a header and one row per entry of the series.
    std::ifstream csv(dir.path / "out" / layer["layer"]["directory"].get<std::string>() / "excavation.csv");
    std::size_t rows = 0;
    for (std::string line; std::getline(csv, line);) ++rows;
    CHECK(rows == x["series"].size() + 1);
  }
  CHECK(e["critical_section"] == critical);
  CHECK(e["margin_min"].get<double>() == smallest);
  CHECK(e["sections"].size() == 2);

  std::ifstream html_in(dir.path / "out" / "report.html");
  const std::string html((std::istreambuf_iterator<char>(html_in)), {});
  CHECK(html.find("Sinking: the wall is weakest at") != std::string::npos);
  CHECK(html.find("<h2>Sinking the shaft</h2>") != std::string::npos);
  const json view = frostwall::report::report_view(dir.path / "out");
  frostwall::test::check_section_filled(view, "has_excavation");
  frostwall::test::check_section_filled(view, "excavation_card");
}

TEST_CASE("An as-built shaft sinks each listed depth on the day given for it", "[excavation][as_built]") {
  // Eight pipes on 1.2 m, straight down: the survey's two sections, dug on
  // their own days, each checked against a 0.2 m wall.
  frostwall::test::TempDir dir("sinking_as_built");
  std::string csv = "pipe,depth,x,y\n";
  for (int k = 0; k < 8; ++k)
    for (const int depth : {0, 30})
      csv += fmt::format("{},{},{:.9f},{:.9f}\n", k + 1, depth, 1.2 * std::cos(k * M_PI / 4),
                         1.2 * std::sin(k * M_PI / 4));
  std::ofstream(dir.path / "survey.csv") << csv;
  const json p = {
      {"name", "sunk as built"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 1.2}, {"count", 8}}}}},
      {"shaft", {{"excavation_radius", 0.7}}},
      {"pipe", {{"diameter", 0.127}, {"temperature", -25.0}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 3.0}, {"initial_temperature", 8.0}, {"far_field", {{"temperature", 8.0}}}}},
      {"time", {{"end", 8}, {"unit", "d"}, {"snapshots", {8}}}},
      {"numerics", {{"spacing", 0.04}}},
      {"design", {{"required_thickness", 0.2}}},
      {"survey", {{"file", "survey.csv"}}},
      {"sections", {{"depths", {10, 20}}}},
      {"excavation", {{"days", {5, 6.5}}, {"air_temperature", 15.0}, {"heat_transfer", 15.0}}},
      {"output", {{"directory", "out"}, {"vtk", false}, {"report", true}}}};
  std::ofstream(dir.path / "project.json") << p.dump(2);
  REQUIRE(frostwall::test::frostwall_cli(dir.path, "run project.json").exit_status == 0);
  std::ifstream summary_in(dir.path / "out" / "summary.json");
  const json s = json::parse(summary_in);
  const json& sections = s["excavation"]["sections"];
  REQUIRE(sections.size() == 2);
  double smallest = 1e300, critical_depth = 0.0;
  for (const auto& section : sections) {
    const double depth = section["depth"];
    CHECK(section["day"].get<double>() == (depth == 10.0 ? 5.0 : 6.5));
    CHECK(section["series"].front()["days_after"].get<double>() == 0.0);
    if (section["margin_min"].get<double>() < smallest) smallest = section["margin_min"], critical_depth = depth;
  }
  CHECK(s["excavation"]["critical_depth"].get<double>() == critical_depth);
  CHECK(s["excavation"]["margin_min"].get<double>() == smallest);
}
