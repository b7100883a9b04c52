// Story: summary.json is one typed contract (summary/summary.hpp). The
// summary a real run returns is the one it wrote; the file read back goes
// through from_json and to_json unchanged, key order included; the typed
// members hold the headline; and every key constant is documented where
// the summary's keys are (docs/reference/*.md, docs/usage.md).
#include <catch2/catch.hpp>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "io/summary_file.hpp"
#include "paths.hpp"
#include "project/project.hpp"
#include "run/run_project.hpp"
#include "summary/summary.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

using namespace frostwall;
using nlohmann::ordered_json;
namespace fs = std::filesystem;
namespace keys = summary::keys;

namespace {

// A small ring (six pipes, 5 cm spacing, 8 days) with a thickness target
// and the error estimate: closure, wall, design, run facts and the error
// entries in a couple of seconds.
project::Project scaled_ring(const fs::path& out) {
  const nlohmann::json j = {
      {"name", "scaled ring for the summary"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 0.8}, {"count", 6}, {"start_angle_deg", 0.0}}}}},
      {"shaft", {{"excavation_radius", 0.5}}},
      {"pipe", {{"diameter", 0.127}, {"temperature", -20.0}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 2.5}, {"initial_temperature", 10.0}, {"far_field", {{"temperature", 10.0}}}}},
      {"time", {{"end", 8}, {"unit", "d"}, {"snapshots", {4, 8}}}},
      {"numerics", {{"placement", "lattice"}, {"spacing", 0.05}, {"error_estimate", true}}},
      {"design", {{"required_thickness", 0.3}}},
      {"output", {{"directory", out.string()}, {"vtk", false}, {"report", false}}}};
  return project::parse_project(j.dump());
}

std::string file_text(const summary::Summary& s) { return summary::to_json(s).dump(2) + "\n"; }

}  // namespace

TEST_CASE("A run's summary goes through the typed Summary unchanged, key order included", "[summary]") {
  test::TempDir dir("frostwall-summary");
  const fs::path out = dir.path / "out";
  const summary::Summary returned = run::run_project(scaled_ring(out), {});
  const std::string text = test::read_text(out / "summary.json");
  const ordered_json file = ordered_json::parse(text);

  // The summary returned is the one written; the file, through the typed
  // structure and back, is the same text: values, spelling and key order.
  CHECK(file_text(returned) == text);
  CHECK(file_text(summary::from_json(file)) == text);
  CHECK(file_text(io::read_summary(out)) == text);

  // The typed members hold the headline the file has.
  CHECK(returned.project == "scaled ring for the summary");
  CHECK(returned.frostwall_version == file[keys::frostwall_version].get<std::string>());
  REQUIRE(returned.closure_time_days);
  CHECK(*returned.closure_time_days == file[keys::closure_time_days].get<double>());
  REQUIRE(returned.wall.size() == 2);
  const auto& last = returned.wall.back();
  REQUIRE(last.day);
  CHECK(*last.day == 8.0);
  REQUIRE(last.min_thickness);
  CHECK(*last.min_thickness == file[keys::wall][1][keys::min_thickness].get<double>());
  REQUIRE(last.OB);
  CHECK(last.OB->thickness == file[keys::wall][1][keys::OB][keys::thickness].get<double>());
  CHECK(summary::wall_at(returned, 4.0) == &returned.wall.front());
  REQUIRE(returned.design);
  CHECK(returned.design->required_thickness == 0.3);
  CHECK(returned.design->pass == file[keys::design][keys::pass].get<bool>());
  REQUIRE(returned.run);
  CHECK(returned.run->spacing == 0.05);
  CHECK(returned.run->particles == file[keys::run][keys::particles].get<std::int64_t>());
  // The error entries sit beside their numbers, in the detail.
  CHECK(returned.block(keys::error_of(keys::closure_time_days).c_str()).is_number());
  CHECK(returned.block(keys::error_estimate)[keys::status] == "done");
  CHECK(last.detail.contains(keys::error_of(keys::min_thickness)));
}

TEST_CASE("The typed Summary keeps any key order and the keys it does not type", "[summary]") {
  // Typed members first, last and between blocks; a null closure; an entry
  // of a wall with a key the type does not know.
  const ordered_json j = ordered_json::parse(R"({
    "warnings": ["w"], "zeta": {"b": 1, "a": 2}, "closure_time_days": null, "project": "p",
    "wall": [{"OB": {"thickness": 0.0, "inner": null, "outer": null}, "day": 1.5, "extra": [1, 2]}],
    "run": {"spacing": 0.1, "a": true, "particles": 12}, "frostwall_version": "0.1.0", "alpha": 1.25
  })");
  const summary::Summary s = summary::from_json(j);
  CHECK(summary::to_json(s).dump() == j.dump());
  CHECK(s.project == "p");
  CHECK_FALSE(s.closure_time_days);
  CHECK(s.has(keys::closure_time_days));
  CHECK_FALSE(s.has(keys::front_contact_days));
  REQUIRE(s.wall.size() == 1);
  CHECK(s.wall[0].day == 1.5);
  CHECK_FALSE(s.wall[0].OA);
  CHECK(s.run->particles == 12);

  // A member set afterwards lands in its slot; one without a slot follows the keys there.
  summary::Summary changed = s;
  changed.closure_time_days = 3.5;
  changed.front_contact_days = 3.0;
  const ordered_json k = summary::to_json(changed);
  std::vector<std::string> order;
  for (auto it = k.begin(); it != k.end(); ++it) order.push_back(it.key());
  CHECK(order == std::vector<std::string>{"warnings", "zeta", "closure_time_days", "project", "wall", "run",
                                          "frostwall_version", "alpha", "front_contact_days"});
  CHECK(k[keys::closure_time_days] == 3.5);
}

TEST_CASE("Every key of the summary is documented", "[summary][docs]") {
  const fs::path docs = fs::path(FROSTWALL_SOURCE_DIR) / "docs";
  std::string text = test::read_text(docs / "usage.md");
  for (const auto& f : fs::directory_iterator(docs / "reference"))
    if (f.path().extension() == ".md") text += "\n" + test::read_text(f.path());
  REQUIRE(text.size() > 10000);
  REQUIRE(std::size(keys::all) >= 60);
  for (const auto key : keys::all) {
    INFO("summary key " << key << " (summary/summary.hpp) is not in docs/reference/*.md or docs/usage.md");
    const std::regex word("(^|[^A-Za-z0-9_])" + std::string(key) + "([^A-Za-z0-9_]|$)");
    CHECK(std::regex_search(text, word));
  }
  CHECK(text.find(std::string("`<key>") + keys::error_suffix + "`") != std::string::npos);
}
