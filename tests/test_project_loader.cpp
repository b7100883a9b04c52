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
#include "paths.hpp"

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

TEST_CASE("single ring with every field of a soil object", "[shared][project]") {
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

TEST_CASE("three-hole layout in built-in clay with a pipe schedule", "[shared][project]") {
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

TEST_CASE("rectangles: the Neumann strip and the soil column", "[shared][project]") {
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

TEST_CASE("measured pipes, anisotropic soil, adiabatic far field, free rings", "[shared][project]") {
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

TEST_CASE("built-in soils", "[shared][project]") {
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

TEST_CASE("every bad case fails with exactly its expected lines", "[shared][project]") {
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

TEST_CASE("files that cannot be read, text that is no project", "[shared][project]") {
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
  // A number beyond a double, and a key given twice: named by their paths.
  CHECK(problems_of(R"({"name": 1e400})", "p.json") ==
        std::vector<std::string>{"name: the number 1e400 is out of range (beyond about 1.8e308)"});
  CHECK(problems_of(R"({"a": {"b": [1, {"c": -2e999}]}})", "p.json") ==
        std::vector<std::string>{"a.b[1].c: the number -2e999 is out of range (beyond about 1.8e308)"});
  CHECK(problems_of(R"({"a": [{"x": 1}, {"x": 1, "y": 2, "x": 3}], "a": 1})", "p.json") ==
        std::vector<std::string>{"a[1].x: given twice in one object (only one value may stand)",
                                 "a: given twice in one object (only one value may stand)"});
  CHECK_THROWS_AS(parse_project("{"), ProjectError);
}

TEST_CASE("implausible but computable input loads with warnings", "[shared][project]") {
  SECTION("the paper's latent heat of clay, decimal point slipped") {
    const Project p = load_edited("single_ring_sand.json", {{"soil", {{"latent_heat", 530718}}}});
    CHECK(p.soil.latent_heat == 530718);
    CHECK(p.warnings ==
          std::vector<std::string>{"soil.latent_heat: 530718 J/kg is more than pure water's 334 kJ/kg; probably a "
                                   "slipped decimal point (53071.8?)"});
  }
  SECTION("a pipe 1 degC above the freezing point") {
    const Project sand = load_edited("single_ring_sand.json", {{"pipe", {{"temperature", 1.0}}}});
    CHECK(sand.warnings ==
          std::vector<std::string>{"pipe.temperature: 1 degC is above the soil's freezing point (0 degC); a pipe this "
                                   "warm cannot freeze the ground"});
    const Project silty = load_edited("two_rings.json", {{"soil", "silty_clay"}, {"pipe", {{"temperature", 0.75}}}});
    CHECK(silty.warnings ==
          std::vector<std::string>{"pipe.temperature: 0.75 degC is above the soil's freezing point (-0.25 degC); a "
                                   "pipe this warm cannot freeze the ground"});
  }
  SECTION("brine warmer than the freezing point") {
    const Project p = load_edited("single_ring_sand.json", {{"pipe",
                                                             {{"temperature", nullptr},
                                                              {"boundary", "brine"},
                                                              {"brine_temperature", 2.0},
                                                              {"heat_transfer_coefficient", 300}}}});
    CHECK(std::get<ShaftSection>(p.geometry).pipe.boundary == PipeBoundary::brine);
    CHECK(std::get<ShaftSection>(p.geometry).pipe.heat_transfer_coefficient == 300);
    CHECK(p.warnings == std::vector<std::string>{
                            "pipe.brine_temperature: 2 degC is above the soil's freezing point (0 degC); a brine this "
                            "warm cannot freeze the ground"});
  }
  SECTION("one schedule point above the freezing point") {
    const Project p =
        load_edited("three_hole_clay.json", {{"pipe", {{"temperature", {{0, 1.0}, {3, -28.0}, {60, -20.0}}}}}});
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

namespace {

// The plate of tests/data/bad/pores_*.json without their mistakes: 300 um
// square, two pores, PD mechanics without a freezing_expansion block.
nlohmann::json porous_plate() {
  return nlohmann::json::parse(R"({
    "name": "porous plate",
    "geometry": { "type": "rectangle", "width": 0.0003, "height": 0.0003,
                  "boundaries": { "top": { "temperature": -10.0 }, "right": { "temperature": -10.0 },
                                  "left": "adiabatic", "bottom": "adiabatic" },
                  "pores": [ { "x": 0.0001, "y": 0.0001, "radius": 2e-5 },
                             { "x": 0.0002, "y": 0.0002, "radius": 1.5e-5 } ] },
    "soil": { "name": "cement paste", "density": 2000.0,
              "unfrozen": { "conductivity": 1.0, "heat_capacity": 900.0 },
              "frozen": { "conductivity": 1.0, "heat_capacity": 900.0 },
              "latent_heat": 0.0, "freezing_point": -100.0 },
    "domain": { "initial_temperature": 5.0 },
    "time": { "end": 10, "unit": "s" },
    "numerics": { "method": "pd", "spacing": 1e-5 },
    "mechanics": { "material": { "elastic_modulus": 25e9, "thermal_expansion": 1e-5,
                                 "reference_temperature": 5.0 } },
    "output": { "directory": "out/porous_plate" }
  })");
}

nlohmann::json patched_plate(const nlohmann::json& patch) {
  auto plate = porous_plate();
  plate.merge_patch(patch);  // null removes a field
  return plate;
}

Project load_plate(const nlohmann::json& patch) { return parse_project(patched_plate(patch).dump()); }

std::vector<std::string> plate_problems(const nlohmann::json& patch) {
  return problems_of(patched_plate(patch).dump(), "plate.json");
}

const nlohmann::json generator = {{"count", 30}, {"radius", {8e-6, 1.5e-5}}, {"min_gap", 2e-6}, {"seed", 7}};

}  // namespace

TEST_CASE("porous plate: listed pores read back, freezing expansion set by default", "[shared][project][pores]") {
  const Project p = load_plate(nlohmann::json::object());
  const auto& plate = std::get<Rectangle>(p.geometry);
  REQUIRE(plate.pores.size() == 2);
  CHECK(plate.pores[0].x == 0.0001);
  CHECK(plate.pores[0].y == 0.0001);
  CHECK(plate.pores[0].radius == 2e-5);
  CHECK(plate.pores[1].x == 0.0002);
  CHECK(plate.pores[1].radius == 1.5e-5);
  CHECK_FALSE(plate.pore_generator);
  CHECK(p.warnings.empty());
  // pores + mechanics: the engines find freezing_expansion set
  REQUIRE(p.mechanics);
  REQUIRE(p.mechanics->freezing_expansion);
  CHECK(p.mechanics->freezing_expansion->model == FreezingExpansion::Model::ice_eigenstrain);
  CHECK(p.mechanics->freezing_expansion->volume_change == 0.09);
  CHECK(p.mechanics->freezing_expansion->ice_elastic_modulus == 9e9);
  CHECK(p.mechanics->frozen_fraction_change == 0.05);

  const Project given = load_plate(
      {{"mechanics",
        {{"freezing_expansion", {{"model", "rim_displacement"}, {"volume_change", 0.1}, {"ice_elastic_modulus", 8e9}}},
         {"relaxation", {{"frozen_fraction_change", 0.02}}}}}});
  const auto& e = *given.mechanics->freezing_expansion;
  CHECK(e.model == FreezingExpansion::Model::rim_displacement);
  CHECK(e.volume_change == 0.1);
  CHECK(e.ice_elastic_modulus == 8e9);
  CHECK(given.mechanics->frozen_fraction_change == 0.02);
  // A plate without pores or mechanics gets neither.
  const Project plain = load_plate({{"geometry", {{"pores", nullptr}}}});
  CHECK(std::get<Rectangle>(plain.geometry).pores.empty());
  CHECK_FALSE(plain.mechanics->freezing_expansion);
  CHECK_FALSE(load_plate({{"mechanics", nullptr}}).mechanics);
}

TEST_CASE("porous plate: drawn pores are reproducible and keep their gaps", "[shared][project][pores]") {
  const Project p = load_plate({{"geometry", {{"pores", generator}}}});
  const auto& plate = std::get<Rectangle>(p.geometry);
  REQUIRE(plate.pore_generator);
  CHECK(plate.pore_generator->count == 30);
  CHECK(plate.pore_generator->radius_min == 8e-6);
  CHECK(plate.pore_generator->radius_max == 1.5e-5);
  CHECK(plate.pore_generator->min_gap == 2e-6);
  CHECK(plate.pore_generator->seed == 7);
  const auto& pores = plate.pores;
  REQUIRE(pores.size() == 30);
  const double gap = 2e-6;
  for (std::size_t i = 0; i < pores.size(); ++i) {
    INFO("pore " << i << " at " << pores[i].x << ", " << pores[i].y << " radius " << pores[i].radius);
    CHECK(pores[i].radius >= 8e-6);
    CHECK(pores[i].radius <= 1.5e-5);
    CHECK(pores[i].x - pores[i].radius >= gap);
    CHECK(pores[i].y - pores[i].radius >= gap);
    CHECK(pores[i].x + pores[i].radius + gap <= plate.width);
    CHECK(pores[i].y + pores[i].radius + gap <= plate.height);
    for (std::size_t j = 0; j < i; ++j) {
      const double dx = pores[i].x - pores[j].x, dy = pores[i].y - pores[j].y;
      const double reach = pores[i].radius + pores[j].radius + gap;
      CHECK(dx * dx + dy * dy >= reach * reach);
    }
  }
  // The radii are drawn, not all alike.
  const auto [smallest, largest] =
      std::minmax_element(pores.begin(), pores.end(), [](const Pore& a, const Pore& b) { return a.radius < b.radius; });
  CHECK(largest->radius - smallest->radius > 1e-6);

  const auto same = [](const std::vector<Pore>& a, const std::vector<Pore>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](const Pore& u, const Pore& v) {
             return u.x == v.x && u.y == v.y && u.radius == v.radius;
           });
  };
  const auto pores_of = [](const Project& q) { return std::get<Rectangle>(q.geometry).pores; };
  CHECK(same(pores, pores_of(load_plate({{"geometry", {{"pores", generator}}}}))));
  auto other_seed = generator;
  other_seed["seed"] = 8;
  const auto other = pores_of(load_plate({{"geometry", {{"pores", other_seed}}}}));
  CHECK(other.size() == 30);
  CHECK_FALSE(same(pores, other));

  // One radius for all; min_gap 0 and seed 1 by default.
  const Project single = load_plate({{"geometry", {{"pores", {{"count", 5}, {"radius", 1e-5}}}}}});
  const auto& g = *std::get<Rectangle>(single.geometry).pore_generator;
  CHECK(g.radius_min == 1e-5);
  CHECK(g.radius_max == 1e-5);
  CHECK(g.min_gap == 0.0);
  CHECK(g.seed == 1);
  for (const auto& pore : pores_of(single)) CHECK(pore.radius == 1e-5);
}

TEST_CASE("porous plate: pore fluid defaults and overrides", "[shared][project][pores]") {
  const PoreFluid defaults = load_plate(nlohmann::json::object()).pore_fluid;
  CHECK(defaults.water_conductivity == 0.6);
  CHECK(defaults.ice_conductivity == 2.14);
  CHECK(defaults.water_heat_capacity == 4182.0);
  CHECK(defaults.ice_heat_capacity == 2060.0);
  CHECK(defaults.water_density == 1000.0);
  CHECK(defaults.ice_density == 920.0);
  CHECK(defaults.latent_heat == 334e3);
  CHECK(defaults.freezing_point == 0.0);

  const Project p = load_plate({{"pore_fluid",
                                 {{"water", {{"conductivity", 0.56}}},
                                  {"ice", {{"density", 917.0}, {"heat_capacity", 2100.0}}},
                                  {"freezing_point", -0.5}}}});
  CHECK(p.pore_fluid.water_conductivity == 0.56);
  CHECK(p.pore_fluid.ice_density == 917.0);
  CHECK(p.pore_fluid.ice_heat_capacity == 2100.0);
  CHECK(p.pore_fluid.freezing_point == -0.5);
  CHECK(p.pore_fluid.water_density == 1000.0);  // not given: kept
  CHECK(p.pore_fluid.ice_conductivity == 2.14);
  CHECK(p.pore_fluid.latent_heat == 334e3);
  CHECK(p.warnings.empty());

  const Project no_pores = load_plate({{"geometry", {{"pores", nullptr}}}, {"pore_fluid", {{"latent_heat", 0}}}});
  CHECK(no_pores.warnings == std::vector<std::string>{"pore_fluid: the plate has no pores (geometry.pores); ignored"});
}

TEST_CASE("porous plate: every problem of pores, pore fluid and freezing expansion", "[shared][project][pores]") {
  CHECK(
      plate_problems({{"pore_fluid", {{"water", {{"conductivity", 0}, {"viscosity", 1e-3}}}, {"latent_heat", -1}}}}) ==
      std::vector<std::string>{"pore_fluid.water.viscosity: unknown field",
                               "pore_fluid.water.conductivity: must be positive, got 0",
                               "pore_fluid.latent_heat: must not be negative, got -1"});
  CHECK(plate_problems(
            {{"geometry", {{"pores", {{"count", 0}, {"radius", {2e-5, 1e-5}}, {"min_gap", -1e-6}, {"seed", -1}}}}}}) ==
        std::vector<std::string>{"geometry.pores.count: must be a positive integer, got 0",
                                 "geometry.pores.radius: must be [min, max] with min <= max, got [2e-05,1e-05]",
                                 "geometry.pores.min_gap: must not be negative, got -1e-06",
                                 "geometry.pores.seed: must be a non-negative integer, got -1"});
  CHECK(plate_problems({{"geometry", {{"pores", nlohmann::json::array()}}}}) ==
        std::vector<std::string>{
            R"(geometry.pores: must list at least one pore (leave "pores" out for a plate without pores))"});
  // A pore may touch a side; the later of two that overlap is named.
  CHECK(plate_problems({{"geometry",
                         {{"pores",
                           {{{"x", 2e-5}, {"y", 2e-5}, {"radius", 2e-5}},
                            {{"x", 1e-4}, {"y", 2e-5}, {"radius", 2e-5}},
                            {{"x", 1.3e-4}, {"y", 5e-5}, {"radius", 3e-5}}}}}}}) ==
        std::vector<std::string>{"geometry.pores[2]: overlaps geometry.pores[1]"});
  CHECK(plate_problems({{"geometry", {{"pores", nullptr}}},
                        {"mechanics", {{"freezing_expansion", {{"model", "rim_displacement"}}}}}}) ==
        std::vector<std::string>{"mechanics.freezing_expansion: the plate has no pores (geometry.pores)"});
  CHECK(plate_problems({{"mechanics",
                         {{"freezing_expansion", {{"model", "ice"}, {"ice_elastic_modulus", 0}}},
                          {"relaxation", {{"frozen_fraction_change", 1.5}}}}}}) ==
        std::vector<std::string>{
            "mechanics.relaxation.frozen_fraction_change: must be at most 1, got 1.5",
            "mechanics.freezing_expansion.model: unknown freezing expansion model 'ice' (expected rim_displacement, "
            "ice_eigenstrain)",
            "mechanics.freezing_expansion.ice_elastic_modulus: must be positive, got 0"});
  CHECK(plate_problems({{"mechanics", {{"freezing_expansion", {{"volume_change", 0.09}}}}}}) ==
        std::vector<std::string>{"mechanics.freezing_expansion.model: required field is missing"});
}

TEST_CASE("porous plate: degrees of saturation per pore, for the plate, and drawn from a range",
          "[shared][project][pores]") {
  // Full pores unless told: the PD paper's case.
  const auto full = std::get<Rectangle>(load_plate(nlohmann::json::object()).geometry);
  for (const auto& pore : full.pores) CHECK(pore.saturation == 1.0);
  // The plate's value for every pore; a pore's own wins.
  auto listed = patched_plate({{"geometry", {{"saturation", 0.9}}}});
  listed["geometry"]["pores"][1]["saturation"] = 0.95;
  const auto plate = std::get<Rectangle>(parse_project(listed.dump()).geometry);
  CHECK(plate.pores[0].saturation == 0.9);
  CHECK(plate.pores[1].saturation == 0.95);
  // A drawn range: every pore inside it, the same again from the same
  // seed, and the pores where they are without the range.
  nlohmann::json ranged = generator;
  ranged["saturation"] = {0.85, 0.99};
  const auto drawn = std::get<Rectangle>(load_plate({{"geometry", {{"pores", ranged}}}}).geometry);
  const auto again = std::get<Rectangle>(load_plate({{"geometry", {{"pores", ranged}}}}).geometry);
  const auto dry = std::get<Rectangle>(load_plate({{"geometry", {{"pores", generator}}}}).geometry);
  REQUIRE(drawn.pores.size() == dry.pores.size());
  double lowest = 1.0, highest = 0.0;
  for (std::size_t k = 0; k < drawn.pores.size(); ++k) {
    CHECK(drawn.pores[k].saturation >= 0.85);
    CHECK(drawn.pores[k].saturation <= 0.99);
    CHECK(drawn.pores[k].saturation == again.pores[k].saturation);
    CHECK(drawn.pores[k].x == dry.pores[k].x);
    CHECK(drawn.pores[k].radius == dry.pores[k].radius);
    CHECK(dry.pores[k].saturation == 1.0);
    lowest = std::min(lowest, drawn.pores[k].saturation), highest = std::max(highest, drawn.pores[k].saturation);
  }
  CHECK(highest - lowest > 0.05);  // 30 draws spread over the range
}
