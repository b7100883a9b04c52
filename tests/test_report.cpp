// Story: an engineer hands report.html to a checking engineer. A coarse run
// of the main job (with a pipe schedule, sensors and design targets, so
// every part of the report has something to show) writes report.html; the
// template is filled everywhere, the page loads nothing from elsewhere, its
// tags balance, it carries one inline map per snapshot and the charts, and
// `frostwall report <dir>` rebuilds it from the files alone. The plotting
// and map helpers are checked on their own.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "cli.hpp"
#include "html_check.hpp"
#include "report/base64.hpp"
#include "report/colour_scale.hpp"
#include "report/mustache_view.hpp"
#include "report/nice_scale.hpp"
#include "report/report.hpp"
#include "report/svg_chart.hpp"
#include "report/templates.hpp"
#include "report/wedge_symmetry.hpp"
#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The main job, coarse (0.1 m) and short (16 days, closed by then), into
// `out`; the brine starts warm (a warning for the report to repeat).
void coarse_main_job(const fs::path& out) {
  std::ifstream in(std::string(FROSTWALL_SOURCE_DIR) + "/projects/single_ring_sand.json");
  json j = json::parse(in);
  j.merge_patch(json::parse(R"({
    "pipe": { "temperature": [[0, 5], [1, -25], [8, -20]] },
    "time": { "end": 16, "snapshots": [4, 8, 16] },
    "numerics": { "spacing": 0.1 },
    "design": { "required_thickness": 0.8, "max_mean_temperature": -1.0 },
    "monitoring": [ { "name": "C1", "r": 5.0, "theta_deg": 6.923 }, { "name": "C2", "x": 3.6, "y": 0.2 } ]
  })"));
  j["output"]["directory"] = out.string();
  run::RunOptions options;
  options.project_text = j.dump(2);
  run::run_project(project::parse_project(options.project_text), options);
}

bool has_key(const json& j, const std::string& key) {
  if (j.is_object()) {
    if (j.contains(key)) return true;
    for (const auto& [k, v] : j.items())
      if (has_key(v, key)) return true;
  } else if (j.is_array()) {
    for (const auto& v : j)
      if (has_key(v, key)) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("The report of a shaft run fills every placeholder, loads nothing and balances its tags", "[report]") {
  test::TempDir dir("frostwall-report");
  const fs::path out = dir.path / "out";
  coarse_main_job(out);
  REQUIRE(fs::exists(out / "report.html"));
  REQUIRE(fs::exists(out / "project.json"));

  // Every name the template uses is in the view (else it would render empty).
  const json view = report::report_view(out);
  for (const auto& name : report::template_names(report::templates::report_html)) {
    INFO(name);
    CHECK(has_key(view, name));
  }
  CHECK(view["has_project"] == true);
  CHECK(view["has_maps"] == true);
  CHECK(view["has_warnings"] == true);

  const std::string html = read(out / "report.html");
  CHECK(html.find("{{") == std::string::npos);
  CHECK(html.find("}}") == std::string::npos);
  CHECK(test::external_references(html).empty());
  CHECK(test::html_balance_problem(html) == "");
  // One inline PNG map per snapshot, as <img> with a data URI.
  CHECK(test::count(html, "<img src=\"data:image/png;base64,") == 3);
  CHECK(test::count(html, "<img ") == 3);
  // Charts: pipe schedule, thickness, OB temperature, OA and OB profiles, sensors.
  CHECK(test::count(html, "<svg class=\"chart\"") == 6);
  CHECK(test::count(html, "<svg class=\"layout\"") == 1);
  CHECK(test::count(html, "<svg class=\"colour-bar\"") == 1);
  // The headline numbers are the summary's.
  const json summary = json::parse(read(out / "summary.json"));
  REQUIRE(summary["closure_time_days"].is_number());
  CHECK(html.find(fmt::format("day {:.1f}", summary["closure_time_days"].get<double>())) != std::string::npos);
  // Closure and front contact side by side, each with its own day.
  REQUIRE(summary["front_contact_days"].is_number());
  CHECK(html.find("Frozen columns touch") != std::string::npos);
  CHECK(html.find(fmt::format("day {:.1f}", summary["front_contact_days"].get<double>())) != std::string::npos);
  CHECK(html.find(summary["design"]["pass"].get<bool>() ? ">PASS<" : ">FAIL<") != std::string::npos);
  for (const char* link : {"href=\"summary.json\"", "href=\"wall.csv\"", "href=\"field_0004.vtu\"", "href=\"ring.pvd\""})
    CHECK(html.find(link) != std::string::npos);

  // Rebuilt from the files alone.
  fs::remove(out / "report.html");
  const auto start = std::chrono::steady_clock::now();
  const auto cli = test::frostwall_cli(dir.path, "--threads 1 report out");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(cli.exit_status == 0);
  REQUIRE(fs::exists(out / "report.html"));
  CHECK(test::html_balance_problem(read(out / "report.html")) == "");
  CHECK(seconds < 5.0);  // the report is part of a run; a coarse one must be quick
}

TEST_CASE("A plain-geometry run without project.json still gets a report", "[report]") {
  test::TempDir dir("frostwall-report-plain");
  auto p = test::rectangle_project(
      0.2, 0.02, R"({ "left": { "temperature": -10 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
      R"("sand")", 5.0, 86400.0, test::numerics(0.005));
  p.output.directory = (dir.path / "out").string();
  run::run_project(p, {});  // no project text: the report must do without project.json
  const std::string html = read(dir.path / "out" / "report.html");
  CHECK(html.find("{{") == std::string::npos);
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("project file was not recorded") != std::string::npos);
  CHECK(html.find("Frozen front") != std::string::npos);
  CHECK(test::count(html, "<img ") == 0);
}

TEST_CASE("frostwall report on a folder without results is bad input", "[report][cli]") {
  test::TempDir dir("frostwall-report-bad");
  fs::create_directory(dir.path / "empty");
  const auto cli = test::frostwall_cli(dir.path, "report empty");
  CHECK(cli.exit_status == 2);
  REQUIRE(cli.stderr_lines.size() == 1);
  CHECK(cli.stderr_lines[0] == "empty: no summary.json here; give the output directory of a frostwall run");
  CHECK(fs::is_empty(dir.path / "empty"));
}

TEST_CASE("Axes get round ticks and journal labels", "[report][chart]") {
  const auto s = report::nice_scale(0.0, 13.6);
  CHECK(s.lo == 0.0);
  CHECK(s.hi == Approx(15.0));
  CHECK(s.step == Approx(5.0));
  CHECK(s.ticks.size() == 4);
  CHECK(report::nice_scale(0.0, 13.6, 7).step == Approx(2.0));
  CHECK(report::tight_scale(0.0, 12.0).hi == Approx(12.0));   // a 12-day axis ends at 12
  CHECK(report::tight_scale(0.0, 120.0).hi == Approx(120.0));
  CHECK(report::tight_scale(-23.0, 15.0).lo == Approx(-25.0));
  const auto t = report::nice_scale(-23.0, 15.0);
  CHECK(t.lo == Approx(-30.0));
  CHECK(t.hi == Approx(20.0));
  CHECK(t.step == Approx(10.0));
  const auto f = report::nice_scale(0.0, 0.83);
  CHECK(f.step == Approx(0.2));
  CHECK(f.decimals == 1);
  const auto flat = report::nice_scale(5.0, 5.0);
  CHECK(flat.lo < 5.0);
  CHECK(flat.hi > 5.0);
  const auto inside = report::ticks_within(-25.0, 15.0, 8);
  CHECK(inside.ticks.front() == Approx(-25.0));
  CHECK(inside.ticks.back() == Approx(15.0));
  CHECK(report::tick_label(-5.0, 0) == "\u22125");
  CHECK(report::tick_label(-0.0001, 1) == "0.0");
  CHECK(report::tick_label(2.5, 1) == "2.5");

  report::Chart c;
  c.title = "t";
  c.x_label = "time (d)";
  c.y_label = "wall thickness (m)";
  c.series.push_back({"OA <a>", {0, 1, 2}, {0, 0.5, std::nan("")}, "", false, true});
  c.series.push_back({"", {0, 2}, {1, 1}, "#000", true, false});
  c.guides.push_back({false, 0.8, "required 0.80 m"});
  const std::string svg = report::render_svg(c);
  CHECK(svg.find(">time (d)</text>") != std::string::npos);
  CHECK(svg.find(">wall thickness (m)</text>") != std::string::npos);
  CHECK(svg.find(">OA &lt;a&gt;</text>") != std::string::npos);  // legend, escaped
  CHECK(svg.find(">required 0.80 m</text>") != std::string::npos);
  CHECK(test::count(svg, "<circle") == 2);  // markers only where y is a number
  CHECK(test::html_balance_problem(svg) == "");
}

TEST_CASE("Base64 of the RFC 4648 test vectors", "[report]") {
  CHECK(report::base64("") == "");
  CHECK(report::base64("f") == "Zg==");
  CHECK(report::base64("fo") == "Zm8=");
  CHECK(report::base64("foo") == "Zm9v");
  CHECK(report::base64("foob") == "Zm9vYg==");
  CHECK(report::base64("fooba") == "Zm9vYmE=");
  CHECK(report::base64("foobar") == "Zm9vYmFy");
}

TEST_CASE("Folding maps every copy of a wedge point back onto it", "[report][map]") {
  for (int M : {1, 3, 26}) {
    report::WedgeSymmetry w{M, 0.3, std::numbers::pi / M};
    for (double f : {0.1, 0.5, 0.9})
      for (double r : {0.5, 5.0}) {
        const particles::Vec<2> x(r * std::cos(w.start + f * w.angle), r * std::sin(w.start + f * w.angle));
        for (std::size_t g = 0; g < w.copies(); ++g) {
          INFO("M = " << M << ", copy " << g);
          CHECK((w.fold(w.apply(g, x)) - x).norm() < 1e-9);
        }
      }
  }
}

TEST_CASE("Colours turn from blue to red at the freezing point", "[report][map]") {
  const report::ColourScale c(-25.0, 15.0, 0.0);
  const auto cold = c(-25.0), zero = c(0.0), warm = c(15.0);
  CHECK(cold[2] > cold[0]);  // blue
  CHECK(warm[0] > warm[2]);  // red
  CHECK(zero[0] == zero[2]); // neutral grey
  CHECK(c(-100.0) == cold);  // clamped
  const std::string bar = c.colour_bar_svg(500);
  CHECK(bar.find("temperature (°C)") != std::string::npos);
  CHECK(bar.find(">\u221225<") != std::string::npos);
  CHECK(bar.find(">15<") != std::string::npos);
  CHECK(test::html_balance_problem(bar) == "");
}

// A PD thermo-mechanical run's report gets a mechanics section: one map of
// the displacement and one of the damage per snapshot (inline PNG), a
// colour bar for each, and the sensors' displacement and damage charts.
TEST_CASE("The report of a PD plate run has displacement and damage maps", "[report][pd]") {
  test::TempDir dir("frostwall-report-pd");
  std::ifstream in(std::string(FROSTWALL_SOURCE_DIR) + "/projects/plate_cooling.json");
  json project = json::parse(in);
  project["numerics"]["spacing"] = 0.0005;
  project["time"] = {{"end", 100}, {"unit", "s"}, {"snapshots", {50, 100}}};
  project["output"]["directory"] = (dir.path / "out").string();
  run::RunOptions options;
  options.project_text = project.dump();
  run::run_project(project::parse_project(project.dump()), options);
  const json view = report::report_view(dir.path / "out");
  CHECK(view["has_mechanics"] == true);
  for (const char* name : {"mechanics_note", "displacement_bar_svg", "damage_bar_svg"}) CHECK(!view[name].get<std::string>().empty());
  CHECK(view["displacement_maps"].size() == 2);
  CHECK(view["damage_maps"].size() == 2);
  const std::string html = read(dir.path / "out" / "report.html");
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("<h2>Mechanics</h2>") != std::string::npos);
  CHECK(test::count(html, "<img src=\"data:image/png;base64,") == 4);  // 2 snapshots x (displacement, damage)
  CHECK(html.find("|displacement| (µm)") != std::string::npos);
  CHECK(html.find("Sensors: displacement along x") != std::string::npos);
  CHECK(html.find("Sensors: damage") != std::string::npos);
}
