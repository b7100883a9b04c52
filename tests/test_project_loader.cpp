// The project loader against the files in tests/data: valid projects load
// with the right numbers, every bad case fails with exactly the lines of its
// .expected file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "project/project.hpp"

namespace fs = std::filesystem;
using namespace frostwall::project;

namespace {

const fs::path data_dir = fs::path(FROSTWALL_SOURCE_DIR) / "tests" / "data";

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  REQUIRE(in);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> read_lines(const fs::path& file) {
  std::vector<std::string> lines;
  std::istringstream in(read_text(file));
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

Project load_valid(const std::string& name) { return load_project((data_dir / "valid" / name).string()); }

// A valid project with one change, for the warning checks.
Project load_edited(const std::string& name, const nlohmann::json& patch) {
  auto project = nlohmann::json::parse(read_text(data_dir / "valid" / name));
  project.merge_patch(patch);
  return parse_project(project.dump());
}

std::vector<std::string> problems_of(const std::string& text, const std::string& source) {
  try {
    parse_project(text, source);
  } catch (const ProjectError& e) {
    return e.problems();
  }
  return {};
}

}  // namespace

TEST_CASE("single ring with every field of a soil object", "[project]") {
  const Project p = load_valid("single_ring_sand.json");
  CHECK(p.name == "Single ring, 26 pipes, medium-coarse sand");
  CHECK_FALSE(p.description.empty());
  REQUIRE(std::holds_alternative<ShaftSection>(p.geometry));
  const auto& s = std::get<ShaftSection>(p.geometry);
  CHECK(s.layout.pattern == Pattern::single);
  CHECK(s.layout.outer_ring.radius == 5.0);
  CHECK(s.layout.outer_ring.count == 26);
  CHECK(s.layout.outer_ring.offset_deg == 0.0);
  CHECK_FALSE(s.layout.inner_ring_radius);
  CHECK(s.shaft.excavation_radius == 3.5);
  CHECK(s.pipe.diameter == 0.127);
  CHECK(s.pipe.temperature.constant());
  CHECK(s.pipe.temperature.at(1e6) == -20.0);
  CHECK(s.pipe.model == PipeModel::disc);
  CHECK(s.outer_radius == 15.0);

  CHECK(p.soil.name == "medium-coarse sand");
  CHECK(p.soil.density == 2090);
  CHECK(p.soil.unfrozen.conductivity == std::array{1.86, 1.86});
  CHECK(p.soil.unfrozen.heat_capacity == 1465.1);
  CHECK(p.soil.frozen.conductivity == std::array{2.56, 2.56});
  CHECK(p.soil.frozen.heat_capacity == 1088.4);
  CHECK_FALSE(p.soil.frozen.anisotropic());
  CHECK(p.soil.latent_heat == 52875.8);
  CHECK(p.soil.freezing_point == 0.0);
  CHECK(p.soil.freezing_range == 0.5);

  CHECK(p.domain.initial_temperature == 15.0);
  CHECK(p.domain.far_field_temperature == 15.0);

  // 120 d = 120 * 86400 s
  CHECK(p.time.unit == TimeUnit::d);
  CHECK(p.time.unit_seconds() == 86400.0);
  CHECK(p.time.end == 10368000.0);
  CHECK(p.time.snapshots ==
        std::vector<double>{864000.0, 1728000.0, 3456000.0, 5184000.0, 6912000.0, 8640000.0, 10368000.0});

  CHECK(p.numerics.spacing == 0.02);
  CHECK(p.numerics.kernel == KernelKind::cubic_spline);
  CHECK(p.numerics.smoothing_ratio == 1.5);
  CHECK(p.numerics.integrator == IntegratorKind::implicit);
  CHECK(p.numerics.beta == 0.05);
  CHECK(p.numerics.conductivity_mean == ConductivityMean::arithmetic);
  CHECK(p.numerics.laplacian == LaplacianForm::plain);

  CHECK(p.design.required_thickness == 2.5);
  CHECK(p.design.max_mean_temperature == -10.0);

  // C1 at r = 5, theta = 6.923 deg: x = 5 cos(0.1208289 rad), y = 5 sin(...)
  REQUIRE(p.monitoring.size() == 2);
  CHECK(p.monitoring[0].name == "C1");
  CHECK(p.monitoring[0].x == Approx(4.963545180).epsilon(1e-9));
  CHECK(p.monitoring[0].y == Approx(0.602676737).epsilon(1e-8));
  CHECK(p.monitoring[1].name == "C2");
  CHECK(p.monitoring[1].x == 6.0);
  CHECK(p.monitoring[1].y == 0.5);

  CHECK(p.output.directory == "out/single_ring_sand");
  CHECK_FALSE(p.output.vtk);
  CHECK(p.output.full_ring);
  CHECK_FALSE(p.output.report);
  CHECK(p.warnings.empty());
}

TEST_CASE("three-hole layout in built-in clay with a pipe schedule", "[project]") {
  const Project p = load_valid("three_hole_clay.json");
  const auto& s = std::get<ShaftSection>(p.geometry);
  CHECK(s.layout.pattern == Pattern::three_hole);
  CHECK(s.layout.outer_ring.radius == 5.0);
  CHECK(s.layout.outer_ring.count == 26);
  CHECK(s.layout.inner_ring_radius == 4.2);
  CHECK_FALSE(s.shaft.excavation_radius);
  CHECK(s.pipe.model == PipeModel::disc);  // the default

  // [[0, -10], [3, -28], [60, -20]] in days
  const auto& schedule = s.pipe.temperature;
  REQUIRE(schedule.points.size() == 3);
  CHECK(schedule.points[1] == std::pair{259200.0, -28.0});
  CHECK(schedule.points[2] == std::pair{5184000.0, -20.0});
  CHECK(schedule.at(-5.0) == -10.0);
  CHECK(schedule.at(1.5 * 86400) == Approx(-19.0));
  CHECK(schedule.at(31.5 * 86400) == Approx(-24.0));
  CHECK(schedule.at(100 * 86400.0) == -20.0);

  // Built-in clay, L with the paper's decimal point mended.
  CHECK(p.soil.density == 2050);
  CHECK(p.soil.unfrozen.conductivity == std::array{1.51, 1.51});
  CHECK(p.soil.frozen.conductivity == std::array{2.05, 2.05});
  CHECK(p.soil.unfrozen.heat_capacity == 1548.8);
  CHECK(p.soil.frozen.heat_capacity == 1172.1);
  CHECK(p.soil.latent_heat == 53071.8);
  CHECK(p.soil.freezing_point == 0.0);

  CHECK(p.domain.far_field_temperature == 15.0);  // default: the initial temperature
  CHECK(p.time.snapshots == std::vector<double>{864000.0, 2592000.0, 5184000.0});

  // Defaults of everything optional.
  CHECK_FALSE(p.numerics.spacing);
  CHECK(p.numerics.kernel == KernelKind::wendland_c2);
  CHECK(p.numerics.smoothing_ratio == 1.3);
  CHECK(p.numerics.integrator == IntegratorKind::rkl2);
  CHECK(p.numerics.beta == 0.1);
  CHECK(p.numerics.conductivity_mean == ConductivityMean::harmonic);
  CHECK(p.numerics.laplacian == LaplacianForm::renormalised);
  CHECK_FALSE(p.design.required_thickness);
  CHECK(p.output.vtk);
  CHECK(p.output.full_ring);
  CHECK(p.output.report);
  CHECK(p.warnings.empty());
}

TEST_CASE("rectangles: the Neumann strip and the soil column", "[project]") {
  const Project neumann = load_valid("neumann_strip.json");
  REQUIRE(std::holds_alternative<Rectangle>(neumann.geometry));
  const auto& strip = std::get<Rectangle>(neumann.geometry);
  CHECK(strip.width == 1.0);
  CHECK(strip.height == 0.02);
  REQUIRE(std::holds_alternative<FixedTemperature>(strip.left));
  CHECK(std::get<FixedTemperature>(strip.left).temperature.at(0.05) == 0.1906);
  CHECK(std::holds_alternative<Adiabatic>(strip.right));
  CHECK(std::holds_alternative<Adiabatic>(strip.top));
  CHECK(std::holds_alternative<Adiabatic>(strip.bottom));
  CHECK(neumann.soil.latent_heat == 1.0);
  CHECK(neumann.soil.freezing_point == 1.0);
  CHECK(neumann.domain.initial_temperature == 1.2);
  CHECK(neumann.time.unit == TimeUnit::s);
  CHECK(neumann.time.end == 0.15);
  CHECK(neumann.time.snapshots == std::vector<double>{0.01, 0.1, 0.15});
  CHECK_FALSE(neumann.output.full_ring);
  CHECK(neumann.warnings.empty());

  const Project column = load_valid("soil_column.json");
  const auto& box = std::get<Rectangle>(column.geometry);
  CHECK(box.width == 0.15);
  CHECK(box.height == 0.20);
  REQUIRE(std::holds_alternative<FixedTemperature>(box.top));
  // top: [[0, 1.0], [0.5, -5.0]] days; a quarter day in it is halfway
  const auto& top = std::get<FixedTemperature>(box.top).temperature;
  CHECK(top.points.back().first == 43200.0);
  CHECK(top.at(21600.0) == Approx(-2.0));
  CHECK(std::get<FixedTemperature>(box.bottom).temperature.at(0.0) == 1.0);
  // 48 h = 172800 s
  CHECK(column.time.unit == TimeUnit::h);
  CHECK(column.time.unit_seconds() == 3600.0);
  CHECK(column.time.end == 172800.0);
  CHECK(column.time.snapshots == std::vector<double>{43200.0, 86400.0, 126000.0, 172800.0});
  CHECK(column.soil.name == "silty clay");
  CHECK(column.soil.freezing_point == -0.25);
  CHECK(column.soil.latent_heat == 33500.0);
}

TEST_CASE("measured pipes, anisotropic soil, adiabatic far field; free rings", "[project]") {
  const Project p = load_valid("measured_pipes.json");
  const auto& s = std::get<ShaftSection>(p.geometry);
  CHECK(s.layout.pattern == Pattern::pipes);
  REQUIRE(s.layout.pipes.size() == 4);
  CHECK(s.layout.pipes[1].x == -0.2);
  CHECK(s.layout.pipes[1].y == 5.03);
  CHECK(s.pipe.model == PipeModel::point);
  CHECK(p.soil.name == "custom soil");
  CHECK(p.soil.unfrozen.conductivity == std::array{1.8, 1.2});
  CHECK(p.soil.frozen.anisotropic());
  CHECK_FALSE(p.domain.far_field_temperature);
  CHECK(p.time.snapshots == std::vector<double>{30 * 86400.0});  // default: the end only
  CHECK(p.monitoring.empty());

  const Project r = load_valid("two_rings.json");
  const auto& rings = std::get<ShaftSection>(r.geometry).layout;
  CHECK(rings.pattern == Pattern::rings);
  REQUIRE(rings.rings.size() == 2);
  CHECK(rings.rings[1].radius == 6.0);
  CHECK(rings.rings[1].count == 30);
  CHECK(rings.rings[1].offset_deg == 6.0);
  CHECK(r.soil.density == 2090);  // built-in sand
}

TEST_CASE("built-in soils", "[project]") {
  CHECK(builtin_soil_names() == std::vector<std::string>{"sand", "clay", "silty_clay"});
  const auto sand = builtin_soil("sand");
  REQUIRE(sand);
  CHECK(sand->density == 2090);
  CHECK(sand->unfrozen.conductivity[0] == 1.86);
  CHECK(sand->frozen.conductivity[1] == 2.56);
  CHECK(sand->unfrozen.heat_capacity == 1465.1);
  CHECK(sand->frozen.heat_capacity == 1088.4);
  CHECK(sand->latent_heat == 52875.8);
  CHECK(sand->freezing_point == 0.0);
  const auto silty = builtin_soil("silty_clay");
  REQUIRE(silty);
  CHECK(silty->density == 1800);
  CHECK(silty->unfrozen.conductivity[0] == 3.05);
  CHECK(silty->frozen.conductivity[0] == 2.68);
  CHECK(silty->unfrozen.heat_capacity == 2124.0);
  CHECK(silty->frozen.heat_capacity == 2508.5);
  CHECK(silty->freezing_range == 0.0);
  CHECK(builtin_soil("clay")->latent_heat == 53071.8);
  CHECK_FALSE(builtin_soil("granite"));
  CHECK_FALSE(builtin_soil("Sand"));
}

TEST_CASE("every bad case fails with exactly its expected lines", "[project]") {
  int cases = 0;
  for (const auto& entry : fs::directory_iterator(data_dir / "bad")) {
    if (entry.path().extension() != ".json") continue;
    ++cases;
    const std::string name = entry.path().stem().string();
    const std::string file = entry.path().filename().string();
    INFO("bad case " << name);
    const fs::path expected_file = entry.path().parent_path() / (name + ".expected");
    REQUIRE(fs::exists(expected_file));
    const auto expected = read_lines(expected_file);
    REQUIRE_FALSE(expected.empty());
    const std::string text = read_text(entry.path());
    // The CLI test checks that this directory never appears.
    CHECK(text.find("\"out/bad_" + name + "\"") != std::string::npos);

    CHECK(problems_of(text, file) == expected);
    try {
      load_project(entry.path().string());
      FAIL("no ProjectError from " << file);
    } catch (const ProjectError& e) {
      CHECK(e.problems().size() == expected.size());
      std::string joined;
      for (const auto& line : e.problems()) joined += (joined.empty() ? "" : "\n") + line;
      CHECK(std::string(e.what()) == joined);
    }
  }
  CHECK(cases >= 20);  // the directory was really read
}

TEST_CASE("files that cannot be read, text that is no project", "[project]") {
  const std::string missing = (data_dir / "no_such_project.json").string();
  try {
    load_project(missing);
    FAIL("no ProjectError");
  } catch (const ProjectError& e) {
    REQUIRE(e.problems().size() == 1);
    CHECK(e.problems()[0] == missing + ": cannot read: No such file or directory");
  }
  CHECK_THROWS_AS(load_project(data_dir.string()), ProjectError);
  CHECK(problems_of("[1, 2]", "p.json") == std::vector<std::string>{"p.json: must be a JSON object, got array"});
  CHECK(problems_of("", "p.json").size() == 1);
  // The parser throws out_of_range, not parse_error, for this one.
  CHECK(problems_of(R"({"name": 1e400})", "p.json") ==
        std::vector<std::string>{"p.json: not valid JSON: number overflow parsing '1e400'"});
  CHECK_THROWS_AS(parse_project("{"), ProjectError);
}

TEST_CASE("implausible but computable input loads with warnings", "[project]") {
  SECTION("the paper's latent heat of clay, decimal point slipped") {
    const Project p = load_edited("single_ring_sand.json", {{"soil", {{"latent_heat", 530718}}}});
    CHECK(p.soil.latent_heat == 530718);
    CHECK(p.warnings == std::vector<std::string>{
                            "soil.latent_heat: 530718 J/kg is more than pure water's 334 kJ/kg; probably a "
                            "slipped decimal point (53071.8?)"});
  }
  SECTION("a pipe 1 degC above the freezing point") {
    const Project sand = load_edited("single_ring_sand.json", {{"pipe", {{"temperature", 1.0}}}});
    CHECK(sand.warnings == std::vector<std::string>{
                               "pipe.temperature: 1 degC is above the soil's freezing point (0 degC); a pipe this "
                               "warm cannot freeze the ground"});
    const Project silty = load_edited("two_rings.json", {{"soil", "silty_clay"}, {"pipe", {{"temperature", 0.75}}}});
    CHECK(silty.warnings == std::vector<std::string>{
                                "pipe.temperature: 0.75 degC is above the soil's freezing point (-0.25 degC); a "
                                "pipe this warm cannot freeze the ground"});
  }
  SECTION("one schedule point above the freezing point") {
    const Project p = load_edited("three_hole_clay.json",
                                  {{"pipe", {{"temperature", {{0, 1.0}, {3, -28.0}, {60, -20.0}}}}}});
    CHECK(p.warnings == std::vector<std::string>{
                            "pipe.temperature[0]: 1 degC is above the soil's freezing point (0 degC); a pipe this "
                            "warm cannot freeze the ground"});
  }
  SECTION("no latent heat at all is pure conduction, neither error nor warning") {
    const Project p = load_edited("single_ring_sand.json", {{"soil", {{"latent_heat", 0}}}});
    CHECK(p.soil.latent_heat == 0.0);
    CHECK(p.warnings.empty());
  }
  SECTION("a pipe at the freezing point is no warning") {
    CHECK(load_edited("single_ring_sand.json", {{"pipe", {{"temperature", 0.0}}}}).warnings.empty());
  }
}
