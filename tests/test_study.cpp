// Story: an engineer chooses a layout with a study. The study file's
// variants (named merge patches, a product of parameter lists, both) expand
// to exactly the projects written out by hand below; a bad study file is
// refused line by line before anything is written; a variant that cannot
// run is reported failed while the others complete; and the shipped layout
// study, run coarse, ranks four-hole before three-hole before single.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.hpp"
#include "html_check.hpp"
#include "study/json_path.hpp"
#include "study/study_file.hpp"
#include "study/study_report.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

using namespace frostwall;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path projects = fs::path(FROSTWALL_SOURCE_DIR) / "projects";

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A base project beside the study (a small shaft case, as written).
const json base_project = json::parse(R"({
  "name": "Base",
  "layout": { "pattern": "single", "outer_ring": { "radius": 5.0, "count": 26 } },
  "pipe": { "diameter": 0.127, "temperature": -20.0 },
  "soil": "sand",
  "domain": { "outer_radius": 15.0, "initial_temperature": 15.0, "far_field": { "temperature": 15.0 } },
  "time": { "end": 30, "unit": "d", "snapshots": [10, 30] },
  "design": { "required_thickness": 2.5 },
  "monitoring": [ { "name": "C1", "r": 5.0, "theta_deg": 3.0 } ],
  "output": { "directory": "ignored", "vtk": false }
})");

study::Study parse(const test::TempDir& dir, const std::string& text) {
  std::ofstream(dir.path / "base.json") << base_project.dump(2);
  return study::parse_study(text, dir.path);
}

std::vector<std::string> names(const study::Study& s) {
  std::vector<std::string> n;
  for (const auto& v : s.variants) n.push_back(v.name);
  return n;
}

std::vector<std::string> problems_of(const test::TempDir& dir, const std::string& text) {
  try {
    parse(dir, text);
  } catch (const study::StudyError& e) {
    return e.problems();
  }
  return {};
}

}  // namespace

TEST_CASE("A product of parameter lists expands to every combination, last parameter fastest", "[shared][study]") {
  test::TempDir dir("frostwall-study");
  const auto s = parse(dir, R"({ "name": "S", "base": "base.json", "output": { "directory": "out/s" },
    "product": [ { "path": "soil", "values": ["sand", "clay"] },
                 { "path": "pipe.temperature", "values": [-20, -30.5] } ] })");
  REQUIRE(names(s) == std::vector<std::string>{"sand+-20", "sand+-30.5", "clay+-20", "clay+-30.5"});
  // The expected projects, by hand: the base with the two values set, its
  // output moved to the variant's folder with the report on, named after it.
  json expected = base_project;
  expected["soil"] = "clay";
  expected["pipe"]["temperature"] = -30.5;
  expected["name"] = "Base (clay+-30.5)";
  expected["output"] = {{"directory", "out/s/clay+-30.5"}, {"vtk", false}, {"report", true}};
  CHECK(s.variants[3].project == expected);
  CHECK(s.variants[3].changes == "soil = \"clay\"; pipe.temperature = -30.5");
  CHECK(s.variants[0].project["soil"] == "sand");
  CHECK(s.variants[0].project["pipe"]["temperature"] == -20);
  CHECK(s.thickness_day == 30.0);  // default: the base's last snapshot
  CHECK(s.base == dir.path / "base.json");
}

TEST_CASE("Named overrides merge into the base and multiply with the product", "[shared][study]") {
  test::TempDir dir("frostwall-study");
  const auto s = parse(dir, R"({ "name": "S", "base": "base.json", "output": { "directory": "o" },
    "patch": { "time": { "end": 20 } },
    "variants": [
      { "name": "three-hole", "patch": { "layout": { "pattern": "three-hole", "inner_ring": { "radius": 4.2 } } } },
      { "name": "no-design", "description": "without targets", "patch": { "design": null, "name": "Other" } } ],
    "product": [ { "path": "/numerics/spacing", "values": [0.05, 0.1], "labels": ["fine", "coarse"] },
                 { "path": "monitoring[0].r", "values": [4.5] } ],
    "rank": { "thickness_day": 12 } })");
  REQUIRE(names(s) == std::vector<std::string>{"three-hole+fine+4.5", "three-hole+coarse+4.5", "no-design+fine+4.5",
                                               "no-design+coarse+4.5"});
  json three_hole = base_project;
  three_hole["time"]["end"] = 20;  // the study's own patch, under every variant
  three_hole["layout"] = {
      {"pattern", "three-hole"}, {"outer_ring", {{"radius", 5.0}, {"count", 26}}}, {"inner_ring", {{"radius", 4.2}}}};
  three_hole["numerics"] = {{"spacing", 0.1}};
  three_hole["monitoring"][0]["r"] = 4.5;
  three_hole["name"] = "Base (three-hole+coarse+4.5)";
  three_hole["output"] = {{"directory", "o/three-hole+coarse+4.5"}, {"vtk", false}, {"report", true}};
  CHECK(s.variants[1].project == three_hole);
  const auto& other = s.variants[2].project;
  CHECK_FALSE(other.contains("design"));  // null removes
  CHECK(other["name"] == "Other");        // a patched name is kept
  CHECK(s.variants[2].changes == "without targets; /numerics/spacing = 0.05; monitoring[0].r = 4.5");
  CHECK(s.thickness_day == 12.0);
}

TEST_CASE("Paths: dotted with indices, or JSON pointers", "[shared][study]") {
  std::string error;
  CHECK(study::parse_path("layout.rings[1].radius", error)->to_string() == "/layout/rings/1/radius");
  CHECK(study::parse_path("/pipe/temperature", error)->to_string() == "/pipe/temperature");
  CHECK_FALSE(study::parse_path("a..b", error).has_value());
  CHECK_FALSE(study::parse_path("[0]", error).has_value());
  CHECK_FALSE(study::parse_path("", error).has_value());
  json doc = {{"a", 1}};
  study::merge_at(doc, json::json_pointer("/b/c"), 2);
  CHECK(doc == json::parse(R"({ "a": 1, "b": { "c": 2 } })"));
  CHECK_THROWS_AS(study::merge_at(doc, json::json_pointer("/a/x"), 3), std::invalid_argument);
}

TEST_CASE("A bad study file is refused with one line per problem, naming the JSON path", "[shared][study]") {
  test::TempDir dir("frostwall-study-bad");
  const std::string head = R"("name": "S", "base": "base.json", "output": { "directory": "o" })";
  CHECK(problems_of(dir, "{ " + head + " }") ==
        std::vector<std::string>{
            "study: a study needs \"variants\" (named merge patches), \"product\" (parameter lists), or both"});
  CHECK(
      problems_of(
          dir,
          R"({ "name": "S", "base": "missing.json", "output": { "directory": "o" }, "variants": [ { "name": "a", "patch": {} } ] })") ==
      std::vector<std::string>{"base: cannot read " + (dir.path / "missing.json").string() +
                               ": No such file or directory"});
  CHECK(problems_of(
            dir, "{ " + head + R"(, "variants": [ { "name": "a", "patch": 3 }, { "name": "b/c", "patch": {} } ] })") ==
        std::vector<std::string>{
            "variants[0].patch: must be an object (a JSON merge patch of the project), got number",
            "variants[1].name: 'b/c' cannot name a folder (use letters, digits and . _ - + =, not starting with '.')"});
  CHECK(problems_of(
            dir, "{ " + head + R"(, "variants": [ { "name": "a", "patch": {} }, { "name": "a", "patch": {} } ] })") ==
        std::vector<std::string>{"variants[1]: duplicate variant name 'a' (also variants[0])"});
  CHECK(problems_of(dir, "{ " + head + R"(, "product": [ { "path": "a..b", "values": [] } ] })") ==
        std::vector<std::string>{
            "product[0].path: not a valid path: 'a..b' (keys separated by '.', array elements as [0])",
            "product[0].values: must list at least one value"});
  CHECK(problems_of(dir,
                    "{ " + head + R"(, "product": [ { "path": "layout", "values": [ { "pattern": "rings" } ] } ] })") ==
        std::vector<std::string>{
            "product[0].values[0]: an object or array value needs a name: give \"labels\" for this parameter"});
  CHECK(problems_of(dir, "{ " + head +
                             R"(, "product": [ { "path": "soil", "values": ["sand", "clay"], "labels": ["s"] } ] })") ==
        std::vector<std::string>{"product[0].labels: must have one label per value (2), got 1"});
  CHECK(
      problems_of(dir, "{ " + head + R"(, "product": [ { "path": "pipe.diameter.x", "values": [1] } ] })") ==
      std::vector<std::string>{
          "product[0].path: cannot set 'pipe.diameter.x' in the base project: /pipe/diameter is a number, not an object"});
  const auto typo = problems_of(dir, "{ " + head + R"(, "varients": [], "rank": { "thickness_day": -1 } })");
  REQUIRE(typo.size() == 3);
  CHECK(typo[0].rfind("varients: ", 0) == 0);
  CHECK(typo[0].find("did you mean 'variants'?") != std::string::npos);
  CHECK(typo[1].rfind("rank.thickness_day: ", 0) == 0);
  CHECK(problems_of(dir, "[1]") == std::vector<std::string>{"study: must be a JSON object, got array"});
}

TEST_CASE("frostwall study with a bad study file exits 2 and writes nothing", "[shared][study][cli]") {
  test::TempDir dir("frostwall-study-cli");
  std::ofstream(dir.path / "bad.json") << R"({ "name": "S", "base": "nowhere.json", "output": { "directory": "out" },
                                             "variants": [ { "name": "a", "patch": {} } ] })";
  const auto cli = test::frostwall_cli(dir.path, "study bad.json");
  CHECK(cli.exit_status == 2);
  REQUIRE(cli.stderr_lines.size() == 1);
  CHECK(cli.stderr_lines[0] == "base: cannot read nowhere.json: No such file or directory");  // beside the study file
  CHECK_FALSE(fs::exists(dir.path / "out"));
}

TEST_CASE("A variant that fails is reported failed while the others complete", "[shared][study][cli]") {
  test::TempDir dir("frostwall-study-fail");
  json s = {{"name", "One bad variant"},
            {"base", (projects / "single_ring_sand.json").string()},
            {"output", {{"directory", "out"}}},
            {"patch", json::parse(R"({ "numerics": { "spacing": 0.1 }, "time": { "end": 4, "snapshots": [2, 4] } })")},
            {"variants", json::parse(R"([ { "name": "good", "patch": {} },
                                          { "name": "bad-diameter", "patch": { "pipe": { "diameter": -1 } } },
                                          { "name": "pipes-in-shaft", "patch": { "shaft": { "excavation_radius": 5.5 } } } ])")}};
  std::ofstream(dir.path / "study.json") << s.dump(2);
  const auto cli = test::frostwall_cli(dir.path, "--threads 1 study study.json");
  CHECK(cli.exit_status == 1);  // some variant failed
  const fs::path out = dir.path / "out";
  CHECK(fs::exists(out / "good" / "report.html"));
  CHECK_FALSE(fs::exists(out / "bad-diameter" / "summary.json"));
  const std::string csv = read(out / "study.csv");
  CHECK(csv.find("1,good,ok,") != std::string::npos);
  CHECK(csv.find(",bad-diameter,failed,") != std::string::npos);
  CHECK(csv.find(",\"pipe.diameter: must be positive, got -1\"\n") != std::string::npos);  // quoted: it has a comma
  CHECK(csv.find(",pipes-in-shaft,failed,") != std::string::npos);
  const std::string html = read(out / "study.html");
  CHECK(html.find("Failed variants") != std::string::npos);
  CHECK(html.find("pipe.diameter: must be positive, got -1") != std::string::npos);
  CHECK(html.find("href=\"good/report.html\"") != std::string::npos);
  CHECK(test::html_balance_problem(html) == "");
  CHECK(test::external_references(html).empty());
  CHECK(html.find("{{") == std::string::npos);
}

TEST_CASE("The shipped layout study, run coarse, ranks four-hole, three-hole, single", "[shared][study]") {
  test::TempDir dir("frostwall-study-layouts");
  json s = json::parse(read(projects / "study_layouts.json"));
  // Coarse and short: the order of closure already shows by day 20.
  s["patch"] = json::parse(R"({ "numerics": { "spacing": 0.1 }, "time": { "end": 20, "snapshots": [10, 20] },
                               "output": { "vtk": false } })");
  s["output"]["directory"] = (dir.path / "out").string();
  const auto study = study::parse_study(s.dump(), projects, "study_layouts.json");
  REQUIRE(study.variants.size() == 4);
  study::StudyOptions options;
  options.jobs = 2;
  const auto run = study::run_and_write_study(study, options);
  const auto standings = study::rank_variants(run, study.thickness_day);
  std::vector<std::string> order;
  for (const auto& st : standings) {
    INFO(st.variant->name << (st.variant->errors.empty() ? "" : ": " + st.variant->errors.front()));
    CHECK(st.variant->ok);
    order.push_back(st.variant->name);
    // The study turns the error estimate on; at 10 cm the coarser twins
    // would exceed the pipe diameter, so each variant says why it has none.
    CHECK(st.variant->summary["error_estimate"]["status"] == "unavailable");
    CHECK(st.variant->summary["error_estimate"]["reason"].get<std::string>().find("numerics.spacing") !=
          std::string::npos);
  }
  CHECK(order == std::vector<std::string>{"four-hole-sand", "three-hole-sand", "single-sand", "single-clay"});
  CHECK(fs::exists(dir.path / "out" / "study.html"));
  const std::string csv = read(dir.path / "out" / "study.csv");
  CHECK(csv.find("\n1,four-hole-sand,ok,") != std::string::npos);
  CHECK(csv.find("\n3,single-sand,ok,") != std::string::npos);
}
