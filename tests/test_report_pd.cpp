// Story: a PD plate whose bonds can break. The shipped plate at 0.5 mm with
// a small fracture energy (0.1 J/m2) cracks as it cools; its report shows
// the damage maps beside the temperature and displacement, and headline
// cards of the broken bonds, the first crack and the crack length. The
// crack length in summary.json (run.mechanics.crack_length) is the length
// of the damage-0.4 lines of the last snapshot's damage field, measured
// here again from the .vtu file.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "html_check.hpp"
#include "post/isoline.hpp"
#include "report/report.hpp"
#include "report/run_files.hpp"
#include "run/run_project.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
namespace fs = std::filesystem;
using nlohmann::json;

TEST_CASE("The report of a PD plate that cracks has damage maps and the crack cards", "[shared][report][pd]") {
  test::TempDir dir("frostwall-report-pd-crack");
  const fs::path out = dir.path / "out";
  std::ifstream in(std::string(FROSTWALL_SOURCE_DIR) + "/projects/plate_cooling.json");
  json project = json::parse(in);
  project["numerics"]["spacing"] = 0.0005;
  project["time"] = {{"end", 100}, {"unit", "s"}, {"snapshots", {50, 100}}};
  project["mechanics"]["material"]["fracture_energy"] = 0.1;
  project["output"]["directory"] = out.string();
  run::RunOptions options;
  options.project_text = project.dump();
  run::run_project(project::parse_project(options.project_text), options);
  report::write_report(out);

  std::ifstream s(out / "summary.json");
  const json summary = json::parse(s);
  const json& m = summary["run"]["mechanics"];
  REQUIRE(m["broken_bonds"].get<double>() > 0);
  REQUIRE(m["first_damage"].is_object());
  REQUIRE(m["crack_length"].is_number());

  // The crack length again, from the last snapshot's file.
  const auto snapshots = report::read_pvd(out / "field.pvd");
  REQUIRE(snapshots.size() == 2);
  const report::SolidSnapshot last = report::read_solid(out / snapshots.back().file);
  REQUIRE(!last.damage.empty());
  const post::IsolineMesh mesh(last.particles.position, 2.5 * summary["run"]["spacing"].get<double>());
  double length = 0.0;
  for (const auto& line : mesh.isolines(last.damage, 0.4)) {
    for (std::size_t k = 1; k < line.points.size(); ++k) length += (line.points[k] - line.points[k - 1]).norm();
    if (line.closed && line.points.size() > 2) length += (line.points.front() - line.points.back()).norm();
  }
  CHECK(length > 0.0);
  CHECK(m["crack_length"].get<double>() == Approx(length).epsilon(1e-6));

  std::ifstream h(out / "report.html");
  std::stringstream text;
  text << h.rdbuf();
  const std::string html = text.str();
  CHECK(test::html_balance_problem(html) == "");
  // Temperature, displacement and damage at each snapshot.
  CHECK(test::count(html, "alt=\"temperature map") == 2);
  CHECK(test::count(html, "alt=\"displacement map") == 2);
  CHECK(test::count(html, "alt=\"damage map") == 2);
  CHECK(html.find("Temperature, displacement and damage") != std::string::npos);
  // The cards carry the summary's numbers.
  const double share = 100.0 * m["broken_bonds"].get<double>() / m["bonds"].get<double>();
  CHECK(html.find(fmt::format(">{:.3g} %<", share)) != std::string::npos);
  CHECK(html.find(fmt::format(">{:.3g} s<", m["first_damage"]["time"].get<double>())) != std::string::npos);
  const double c = m["crack_length"].get<double>();
  CHECK(html.find(c < 1e-3 ? fmt::format(">{:.3g} µm<", 1e6 * c) : fmt::format(">{:.3g} mm<", 1e3 * c)) != std::string::npos);
  for (const char* label : {">Broken bonds<", ">First crack<", ">Crack length<"}) {
    INFO(label);
    CHECK(html.find(label) != std::string::npos);
  }
  CHECK(html.find("breaks at stretch") != std::string::npos);
}

// A porous plate without a solid (no mechanics block): the pores freeze but
// nothing can crack. Its temperature maps stand in the maps section (the
// frost section has no solid to draw), the cards say how the pores froze
// and nothing of cracks or bonds.
TEST_CASE("The report of a porous plate without a solid has temperature maps and no crack cards", "[shared][report][frost]") {
  test::TempDir dir("frostwall-report-frost-heat");
  const fs::path out = dir.path / "out";
  std::ifstream in(std::string(FROSTWALL_SOURCE_DIR) + "/projects/mortar_frost.json");
  json project = json::parse(in);
  project.erase("mechanics");
  project["numerics"]["spacing"] = 8e-6;
  project["time"] = {{"end", 0.008}, {"unit", "s"}, {"snapshots", {0.004, 0.008}}};
  project["output"]["directory"] = out.string();
  run::RunOptions options;
  options.project_text = project.dump();
  run::run_project(project::parse_project(options.project_text), options);
  const json view = report::report_view(out);
  CHECK(view["has_frost"] == true);
  CHECK(view["has_mechanics"] == false);
  CHECK(view["has_maps"] == true);
  CHECK(view["maps"].size() == report::read_pvd(out / "field.pvd").size());
  const std::string html = report::render_report(out);
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::count(html, "alt=\"temperature map") == 2);
  CHECK(html.find(">Pores frozen<") != std::string::npos);
  for (const char* absent : {">Pores cracked<", ">Broken bonds<", ">First crack<", "<h2>Mechanics</h2>"}) {
    INFO(absent);
    CHECK(html.find(absent) == std::string::npos);
  }
}
