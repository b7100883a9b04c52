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
#include "report_view_check.hpp"
#include "io/point_cloud_vtk.hpp"
#include "report/base64.hpp"
#include "report/colour_scale.hpp"
#include "report/field_map.hpp"
#include "report/mustache_view.hpp"
#include "report/nice_scale.hpp"
#include "report/report.hpp"
#include "report/svg_chart.hpp"
#include "report/templates.hpp"
#include "report/wedge_symmetry.hpp"
#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

using namespace frostwall;
using test::has_key;
using test::split_section;
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
  report::write_report(out);  // as the frostwall command does after a run
}

// The output directory of a porous plate's run, written by hand with the
// files a frost run leaves: a 24 x 24 lattice (10 µm spacing) with three
// pores, two snapshots in field.pvd whose particles carry temperature,
// liquid fraction, damage, pore id and material; summary.json with the
// pores (one frozen, one still freezing, one not started) and damage.csv.
// Without `pores` the same directory of a plain PD plate. Returns the summary.
json write_frost_output(const fs::path& out, bool pores) {
  fs::create_directories(out);
  const double s = 1e-5;
  const int n = 24;
  const json pore_list = json::parse(R"([
    {"id": 0, "x": 6.0e-5, "y": 1.7e-4, "radius": 3.0e-5, "freezing_start": 0.0041, "freezing_end": 0.0093, "max_rim_damage": 0.63},
    {"id": 1, "x": 1.7e-4, "y": 7.0e-5, "radius": 4.0e-5, "freezing_start": 0.006, "freezing_end": null, "max_rim_damage": 0.2},
    {"id": 2, "x": 1.8e-4, "y": 1.9e-4, "radius": 2.0e-5, "freezing_start": null, "freezing_end": null, "max_rim_damage": 0.0}])");
  const std::vector<double> times{0.005, 0.01};
  std::vector<io::PvdEntry> pvd;
  for (std::size_t k = 0; k < times.size(); ++k) {
    io::PointCloudFrame f;
    std::vector<double> T, lf, damage, pore_id, material, volume, boundary, u;
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) * s, y = (j + 0.5) * s;
        int pore = -1;
        double rim = 1.0;  // distance beyond pore 0's rim, in spacings
        for (std::size_t p = 0; p < pore_list.size(); ++p) {
          const auto& q = pore_list[p];
          const double r = std::hypot(x - q["x"].get<double>(), y - q["y"].get<double>()) - q["radius"].get<double>();
          if (r <= 0.0) pore = int(p);
          if (p == 0) rim = r / s;
        }
        const bool ice = pore == 0 && k == 1;  // pore 0 frozen at the second snapshot
        f.points.push_back({x, y, 0.0});
        T.push_back(2.0 - 400.0 * times[k] * y / (n * s));
        lf.push_back(pore < 0 ? 1.0 : (ice ? 0.0 : 1.0));
        damage.push_back(k == 1 && rim > 0 && rim < 2 ? 0.5 : 0.0);
        pore_id.push_back(pore);
        material.push_back(pore < 0 ? 0 : (ice ? 2 : 1));
        volume.push_back(s * s);
        boundary.push_back(-1);
        u.insert(u.end(), {1e-9 * i, 0.0, 0.0});
      }
    f.fields = {{"temperature", T},     {"liquid_fraction", lf}, {"damage", damage},    {"pore_id", pore_id},
                {"material", material}, {"volume", volume},      {"boundary", boundary}};
    f.vectors = {{"displacement", u}};
    const std::string file = fmt::format("field_{:04d}.vtu", k + 1);
    io::write_vtu(out / file, f);
    pvd.push_back({times[k], file});
  }
  io::write_pvd(out / "field.pvd", pvd);
  json summary = {
      {"project", "porous plate by hand"},
      {"frostwall_version", "test"},
      {"front", json::array()},
      {"run", {{"time_unit", "s"}, {"spacing", s}, {"smoothing_length", 1.3 * s}, {"kernel", "wendland_c2"}}}};
  if (pores) {
    summary["pores"] = pore_list;
    summary["all_pores_frozen"] = nullptr;
    summary["damage"] = summary["cracks"] = json::array();
    for (std::size_t k = 0; k < times.size(); ++k) {
      summary["damage"].push_back({{"time", times[k]},
                                   {"broken_bond_share", 0.01},
                                   {"largest_damage", 0.5},
                                   {"damaged_area", 1e-11},
                                   {"crack_length", 2.5e-4 * (k + 1)},
                                   {"crack_length_per_area", 4e3 * (k + 1)},
                                   {"broken_bond_energy", 1.5e-3 * (k + 1)}});
      summary["cracks"].push_back({{"t", times[k]}, {"file", fmt::format("cracks_{:04d}.vtp", k + 1)}});
    }
    std::ofstream csv(out / "damage.csv");
    csv << "time,broken_bond_share,largest_damage,damaged_area\n";
    for (int r = 0; r <= 9; ++r) csv << fmt::format("{},{},{},{}\n", 0.001 * (r + 1), 0.002 * r, 0.08 * r, 1e-12 * r);
  }
  std::ofstream(out / "summary.json") << summary.dump(1);
  return summary;
}

// The coordinate pairs of the first data polyline of a chart.
std::size_t polyline_points(const std::string& svg) {
  const std::size_t line = svg.find("<polyline stroke=");
  if (line == std::string::npos) return 0;
  const std::size_t a = svg.find("points=\"", line) + 8, b = svg.find('"', a);
  return test::count(svg.substr(a, b - a), ",");
}

}  // namespace

TEST_CASE("The report of a shaft run fills every placeholder, loads nothing and balances its tags",
          "[shared][report]") {
  test::TempDir dir("frostwall-report");
  const fs::path out = dir.path / "out";
  coarse_main_job(out);
  REQUIRE(fs::exists(out / "report.html"));
  REQUIRE(fs::exists(out / "project.json"));

  // Every name the template uses is in the view (else it would render
  // empty); the frost damage section's own names are checked on a porous
  // plate's view.
  const json view = report::report_view(out);
  // (The wall check and brine sections' names: tests/test_layers.cpp; the
  // as-built and failed-pipe sections': tests/test_as_built.cpp; the
  // calibration's: tests/test_calibrate.cpp; the plant's: tests/test_plant_project.cpp.)
  std::string thermal(report::templates::report_html);
  // (A plain geometry's cards: the PD plate's and porous plate's tests.)
  for (const char* section :
       {"has_frost", "has_cfd_dem", "has_groundwater", "has_wall_check", "has_brine", "has_cards", "has_as_built",
        "has_intact_pair", "has_calibration", "has_plant", "plant_card", "has_excavation", "excavation_card"})
    thermal = split_section(thermal, section).second;
  for (const auto& name : report::template_names(thermal)) {
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
  // Charts: freezing curve, pipe schedule, thickness, OB temperature, OA and OB profiles, sensors.
  CHECK(test::count(html, "<svg class=\"chart\"") == 7);
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
  // The pipe model is named, as the summary has it.
  CHECK(summary["run"]["pipe_model"] == "resolved");
  CHECK(html.find("(resolved model)") != std::string::npos);
  for (const char* link :
       {"href=\"summary.json\"", "href=\"wall.csv\"", "href=\"field_0004.vtu\"", "href=\"ring.pvd\""})
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

TEST_CASE("A plain-geometry run without project.json still gets a report", "[shared][report]") {
  test::TempDir dir("frostwall-report-plain");
  auto p = test::rectangle_project(
      0.2, 0.02,
      R"({ "left": { "temperature": -10 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
      R"("sand")", 5.0, 86400.0, test::numerics(0.005));
  p.output.directory = (dir.path / "out").string();
  run::run_project(p, {});  // no project text: the report must do without project.json
  report::write_report(p.output.directory);
  const std::string html = read(dir.path / "out" / "report.html");
  CHECK(html.find("{{") == std::string::npos);
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("project file was not recorded") != std::string::npos);
  CHECK(html.find("SPH heat conduction") != std::string::npos);
  // The front formed (a -10 °C face in sand): its card, at the summary's last position.
  const json summary = json::parse(read(dir.path / "out" / "summary.json"));
  REQUIRE(!summary["front"].empty());
  REQUIRE(summary["front"].back()[1].get<double>() > 0.0);
  CHECK(html.find(">Frozen front, ") != std::string::npos);
  CHECK(html.find(report::tick_label(summary["front"].back()[1].get<double>(), 4) + " m<") != std::string::npos);
  // A temperature map per snapshot, no pipes or design targets.
  const auto snapshots = report::read_pvd(dir.path / "out" / "field.pvd");
  REQUIRE(!snapshots.empty());
  CHECK(test::count(html, "alt=\"temperature map") == snapshots.size());
  CHECK(test::count(html, "<img ") == snapshots.size());
  CHECK(html.find("Pipe temperature") == std::string::npos);
  CHECK(html.find("Design targets") == std::string::npos);
}

TEST_CASE("frostwall report on a folder without results is bad input", "[shared][report][cli]") {
  test::TempDir dir("frostwall-report-bad");
  fs::create_directory(dir.path / "empty");
  const auto cli = test::frostwall_cli(dir.path, "report empty");
  CHECK(cli.exit_status == 2);
  REQUIRE(cli.stderr_lines.size() == 1);
  CHECK(cli.stderr_lines[0] == "empty: no summary.json here; give the output directory of a frostwall run");
  CHECK(fs::is_empty(dir.path / "empty"));
}

TEST_CASE("Axes get round ticks and journal labels", "[shared][report][chart]") {
  const auto s = report::nice_scale(0.0, 13.6);
  CHECK(s.lo == 0.0);
  CHECK(s.hi == Approx(15.0));
  CHECK(s.step == Approx(5.0));
  CHECK(s.ticks.size() == 4);
  CHECK(report::nice_scale(0.0, 13.6, 7).step == Approx(2.0));
  CHECK(report::tight_scale(0.0, 12.0).hi == Approx(12.0));  // a 12-day axis ends at 12
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

TEST_CASE("Base64 of the RFC 4648 test vectors", "[shared][report]") {
  CHECK(report::base64("") == "");
  CHECK(report::base64("f") == "Zg==");
  CHECK(report::base64("fo") == "Zm8=");
  CHECK(report::base64("foo") == "Zm9v");
  CHECK(report::base64("foob") == "Zm9vYg==");
  CHECK(report::base64("fooba") == "Zm9vYmE=");
  CHECK(report::base64("foobar") == "Zm9vYmFy");
}

TEST_CASE("Folding maps every copy of a wedge point back onto it", "[shared][report][map]") {
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

TEST_CASE("Colours turn from blue to red at the freezing point", "[shared][report][map]") {
  const report::ColourScale c(-25.0, 15.0, 0.0);
  const auto cold = c(-25.0), zero = c(0.0), warm = c(15.0);
  CHECK(cold[2] > cold[0]);   // blue
  CHECK(warm[0] > warm[2]);   // red
  CHECK(zero[0] == zero[2]);  // neutral grey
  CHECK(c(-100.0) == cold);   // clamped
  const std::string bar = c.colour_bar_svg(500);
  CHECK(bar.find("temperature (°C)") != std::string::npos);
  CHECK(bar.find(">\u221225<") != std::string::npos);
  CHECK(bar.find(">15<") != std::string::npos);
  CHECK(test::html_balance_problem(bar) == "");
}

// A porous plate's report gets a frost damage section: per snapshot the
// temperature, material and damage maps side by side, one freezing bar per
// pore (open when unfinished, a note when never started, a marker when all
// froze), the damage over time from damage.csv and a table of the pores. A
// run without pores has no such section.
TEST_CASE("The report of a porous plate has a frost damage section", "[shared][report][frost]") {
  test::TempDir dir("frostwall-report-frost");
  const fs::path out = dir.path / "out";
  json summary = write_frost_output(out, true);
  const auto& pores = summary["pores"];
  const std::size_t snapshots = 2, rows = report::read_csv(out / "damage.csv").rows();
  std::size_t open = 0, never = 0;
  for (const auto& p : pores) {
    open += p["freezing_start"].is_number() && p["freezing_end"].is_null();
    never += p["freezing_start"].is_null();
  }
  REQUIRE(open > 0);
  REQUIRE(never > 0);

  json view = report::report_view(out);
  CHECK(view["has_frost"] == true);
  for (const auto& name : report::template_names(split_section(report::templates::report_html, "has_frost").first)) {
    INFO(name);
    CHECK(has_key(view, name));
  }
  REQUIRE(view["frost_snapshots"].size() == snapshots);
  for (const auto& s : view["frost_snapshots"]) CHECK(s["maps"].size() == 3);  // temperature, material, damage
  REQUIRE(view["pore_rows"].size() == pores.size());
  for (std::size_t k = 0; k < pores.size(); ++k) {
    CHECK(view["pore_rows"][k]["pore"] == pores[k]["id"].dump());  // in the order listed
    CHECK(view["pore_rows"][k]["radius"] == report::tick_label(1e6 * pores[k]["radius"].get<double>(), 1));
  }
  // One bar per pore, labelled by its id; no marker while not all froze.
  const std::string bars = view["pore_bars_svg"];
  CHECK(test::count(bars, "<g class=\"bar") == pores.size());
  CHECK(test::count(bars, "<g class=\"bar open\"") == open);
  CHECK(test::count(bars, "<g class=\"bar never\"") == never);
  for (const auto& p : pores) CHECK(bars.find(">pore " + p["id"].dump() + "<") != std::string::npos);
  CHECK(bars.find("all pores frozen") == std::string::npos);
  CHECK(test::html_balance_problem(bars) == "");
  // The crack table: a row per snapshot, in the units of its header.
  REQUIRE(view["crack_rows"].size() == snapshots);
  CHECK(view["crack_rows"][1]["length"] == "500");  // 5e-4 m in um
  CHECK(view["crack_rows"][1]["per_area"] == "8");  // 8e3 /m in /mm
  CHECK(view["crack_rows"][1]["energy"] == "3");    // 3e-3 J/m in mJ/m
  CHECK(view["crack_rows"][1]["file"] == "cracks_0002.vtp");
  // Broken bonds and largest damage, every row of damage.csv a point.
  REQUIRE(view["frost_charts"].size() == 2);
  for (const auto& c : view["frost_charts"]) CHECK(polyline_points(c["svg"].get<std::string>()) == rows);

  const std::string html = report::render_report(out);
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("<h2>Frost damage</h2>") != std::string::npos);
  CHECK(html.find("Frost damage of a porous solid") != std::string::npos);
  CHECK(html.find(">Pores frozen<") != std::string::npos);
  CHECK(html.find(">1 of 3<") != std::string::npos);  // one pore's freezing_end
  CHECK(html.find(">Saturation<") != std::string::npos);
  CHECK(test::count(html, "alt=\"temperature map") == snapshots);
  CHECK(test::count(html, "<img src=\"data:image/png;base64,") == 3 * snapshots);
  CHECK(test::count(html, "alt=\"material map") == snapshots);
  CHECK(html.find("href=\"damage.csv\"") != std::string::npos);

  // Once every pore froze: closed bars only and a marker where the last one did.
  double last = 0.0;
  for (auto& p : summary["pores"]) {
    if (p["freezing_start"].is_null()) p["freezing_start"] = 0.002;
    if (p["freezing_end"].is_null()) p["freezing_end"] = 0.0098;
    last = std::max(last, p["freezing_end"].get<double>());
  }
  summary["all_pores_frozen"] = last;
  std::ofstream(out / "summary.json") << summary.dump(1);
  view = report::report_view(out);
  const std::string closed = view["pore_bars_svg"];
  CHECK(test::count(closed, "<g class=\"bar\"") == pores.size());
  CHECK(closed.find(">all pores frozen<") != std::string::npos);
  for (const auto& c : view["frost_charts"])
    CHECK(c["svg"].get<std::string>().find(">all pores frozen<") != std::string::npos);

  // The same plate without pores: no such section.
  const fs::path plain = dir.path / "plain";
  write_frost_output(plain, false);
  view = report::report_view(plain);
  CHECK(view["has_frost"] == false);
  CHECK(view["pore_rows"].empty());
  const std::string plain_html = report::render_report(plain);
  CHECK(plain_html.find("Frost damage") == std::string::npos);
  CHECK(plain_html.find("id=\"frost\"") == std::string::npos);
  CHECK(test::html_balance_problem(plain_html) == "");
}

// The material map does not blend categories: every painted pixel has one
// of the materials' colours (a kernel average would mix them at a rim).
TEST_CASE("A category map paints each pixel with its nearest particle's colour", "[shared][report][map]") {
  report::FieldSnapshot lattice;
  const double s = 0.1;
  std::vector<std::array<std::uint8_t, 3>> colours;
  const std::array<std::array<std::uint8_t, 3>, 2> palette{{{200, 0, 0}, {0, 0, 200}}};
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 10; ++i) {
      lattice.position.emplace_back((i + 0.5) * s, (j + 0.5) * s);
      lattice.volume.push_back(s * s);
      lattice.boundary.push_back(-1);
      lattice.temperature.push_back(0.0);
      colours.push_back(palette[std::hypot((i + 0.5) * s - 0.5, (j + 0.5) * s - 0.5) < 0.3 ? 1 : 0]);
    }
  report::MapWindow window;
  window.size = 1.0;
  window.pixels = 50;
  const report::FieldMap map(lattice, report::WedgeSymmetry{}, "wendland_c2", 1.3 * s, s, window, 0.0);
  const auto image = map.nearest_raster(colours);
  std::size_t painted = 0, inner = 0, blended = 0;
  for (std::size_t k = 0; k < image.pixels.size(); k += 4) {
    const std::array<std::uint8_t, 3> c{image.pixels[k], image.pixels[k + 1], image.pixels[k + 2]};
    if (image.pixels[k + 3] == 0) continue;
    ++painted;
    inner += c == palette[1];
    blended += c != palette[0] && c != palette[1];
  }
  CHECK(blended == 0);
  CHECK(painted == image.pixels.size() / 4);  // the lattice covers the window
  // The inner disc's particles own their share of the pixels (a quarter each: 10 x 10 particles, 50 x 50 pixels).
  std::size_t disc = 0;
  for (const auto& c : colours) disc += c == palette[1];
  CHECK(inner == 25 * disc);
}
