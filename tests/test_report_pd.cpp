// Story: the report of a PD plate shows the plate's physics. The shipped
// plate, whose bonds cannot break, gets temperature and displacement maps
// and no damage maps. With a small fracture energy (0.1 J/m2) the plate
// cracks as it cools: its report shows the damage maps beside the
// temperature and displacement, and headline cards of the broken bonds,
// the first crack and the crack length. The crack length in summary.json
// (run.mechanics.crack_length) is the length of the damage-0.4 lines of the
// last snapshot's damage field, measured here again from the .vtu file. A
// porous plate without a solid gets temperature maps and no crack cards.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "html_check.hpp"
#include "report_view_check.hpp"
#include "post/isoline.hpp"
#include "report/mustache_view.hpp"
#include "report/report.hpp"
#include "report/run_files.hpp"
#include "report/templates.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

using namespace frostwall;
namespace fs = std::filesystem;
using nlohmann::json;

// The shipped plate (no fracture energy) at 0.5 mm: a mechanics section
// with the temperature beside the displacement per snapshot (inline PNG),
// no damage maps, the sensors' displacement and damage charts; the title
// and cards are the solid's, and nothing of a shaft appears.
TEST_CASE("The report of a PD plate run has temperature and displacement maps, no damage maps",
          "[shared][report][pd]") {
  test::TempDir dir("frostwall-report-pd");
  test::run_shipped(
      "plate_cooling.json",
      {{"numerics", {{"spacing", 0.0005}}}, {"time", {{"end", 100}, {"unit", "s"}, {"snapshots", {50, 100}}}}},
      dir.path / "out");
  const json view = report::report_view(dir.path / "out");
  const json summary = json::parse(test::read_text(dir.path / "out" / "summary.json"));
  REQUIRE(summary["run"]["mechanics"]["critical_stretch"].is_null());  // no fracture energy: bonds cannot break
  CHECK(view["has_mechanics"] == true);
  for (const auto& name :
       report::template_names(test::split_section(report::templates::report_html, "has_mechanics").first)) {
    INFO(name);
    CHECK(test::has_key(view, name));
  }
  // Temperature beside displacement at each snapshot; no damage maps for unbreakable bonds.
  REQUIRE(view["mechanics_snapshots"].size() == 2);
  for (const auto& row : view["mechanics_snapshots"]) CHECK(row["maps"].size() == 2);
  CHECK(view["has_damage_maps"] == false);
  CHECK(view["has_maps"] == false);  // the temperature is in the mechanics section
  const std::string html = test::read_text(dir.path / "out" / "report.html");
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("<h2>Mechanics</h2>") != std::string::npos);
  CHECK(test::count(html, "<img src=\"data:image/png;base64,") == 4);
  CHECK(test::count(html, "alt=\"temperature map") == 2);
  CHECK(test::count(html, "alt=\"displacement map") == 2);
  CHECK(test::count(html, "alt=\"damage map") == 0);
  CHECK(html.find("|displacement| (µm)") != std::string::npos);
  CHECK(html.find("Sensors: displacement along x") != std::string::npos);
  // The title names the method; the headline is the solid's; no shaft parts.
  CHECK(html.find("bond-based peridynamic (PD) mechanics") != std::string::npos);
  CHECK(html.find("Artificial ground freezing") == std::string::npos);
  const double largest = summary["run"]["mechanics"]["largest_displacement"];
  CHECK(html.find(fmt::format(">{:.3g} µm<", 1e6 * largest)) != std::string::npos);
  CHECK(html.find(">Largest displacement<") != std::string::npos);
  CHECK(html.find(">Sensor A, 100 s<") != std::string::npos);
  CHECK(html.find("the bonds cannot break") != std::string::npos);
  for (const char* absent : {"Frozen front", "Pipe temperature", "Design targets", "Wendland",
                             "RKL2 super-time-stepping, step", "latent heat per particle", "smoothing length"}) {
    INFO(absent);
    CHECK(html.find(absent) == std::string::npos);
  }
  CHECK(html.find("horizon") != std::string::npos);
  CHECK(html.find("bonds never break") != std::string::npos);
}

TEST_CASE("The report of a PD plate that cracks has damage maps and the crack cards", "[shared][report][pd]") {
  test::TempDir dir("frostwall-report-pd-crack");
  const fs::path out = dir.path / "out";
  test::run_shipped("plate_cooling.json",
                    {{"numerics", {{"spacing", 0.0005}}},
                     {"time", {{"end", 100}, {"unit", "s"}, {"snapshots", {50, 100}}}},
                     {"mechanics", {{"material", {{"fracture_energy", 0.1}}}}}},
                    out);

  const json summary = json::parse(test::read_text(out / "summary.json"));
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

  const std::string html = test::read_text(out / "report.html");
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
  CHECK(html.find(c < 1e-3 ? fmt::format(">{:.3g} µm<", 1e6 * c) : fmt::format(">{:.3g} mm<", 1e3 * c)) !=
        std::string::npos);
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
TEST_CASE("The report of a porous plate without a solid has temperature maps and no crack cards",
          "[shared][report][frost]") {
  test::TempDir dir("frostwall-report-frost-heat");
  const fs::path out = dir.path / "out";
  test::run_shipped("mortar_frost.json",
                    {{"mechanics", nullptr},
                     {"numerics", {{"spacing", 8e-6}}},
                     {"time", {{"end", 0.008}, {"unit", "s"}, {"snapshots", {0.004, 0.008}}}}},
                    out);
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
