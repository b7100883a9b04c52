// Story: a project the machine cannot hold is refused before any particle
// is placed, so the estimate must be close to what placement then makes.
// The estimate (freezing/capacity.hpp) integrates the spacing the placement asks
// for over the simulated region; it is compared with the particles the
// builder actually places: the graded main job at two spacings, a graded
// four-hole, a lattice wedge, the full ring (symmetry off) and a graded
// rectangle. The refusal names the field and a value that fits.
#include <catch2/catch.hpp>
#include <fmt/core.h>

#include "freezing/capacity.hpp"
#include "freezing/model.hpp"
#include "support.hpp"

using namespace frostwall;
using nlohmann::json;

TEST_CASE("capacity: the estimated particle count is within 10 % of the placed one", "[freezing][capacity]") {
  struct Case {
    const char* name;
    project::Project project;
  };
  const json lattice = {{"numerics", {{"placement", "lattice"}, {"spacing", 0.05}}}};
  const std::vector<Case> cases = {
      {"single ring, graded 2 cm (main job)", test::shipped_project("single_ring_sand.json", json::object())},
      {"single ring, graded 4 cm", test::shipped_project("single_ring_sand.json", {{"numerics", {{"spacing", 0.04}}}})},
      {"four-hole, graded default", test::shipped_project("four_hole_sand.json", json::object())},
      {"single ring, lattice 5 cm", test::shipped_project("single_ring_sand.json", lattice)},
      {"single ring, full ring at 10 cm",
       test::shipped_project("single_ring_sand.json", {{"numerics", {{"spacing", 0.1}, {"symmetry", "off"}}}})},
      {"rectangle, graded",
       test::rectangle_project(
           1.0, 0.5, R"({"left": {"temperature": 0}, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic"})",
           test::unit_soil(0.5, 1.0), 1.0, 0.1, R"({"spacing": 0.01, "placement": "graded"})")},
  };
  for (const auto& c : cases) {
    const auto estimate = freezing::estimate_capacity(c.project, freezing::resolved_spacing(c.project));
    const auto m = freezing::build_model(c.project);
    const double placed = static_cast<double>(m.model->free_count());
    fmt::print("capacity, {}: estimated {:.0f}, placed {:.0f} ({:+.1f} %)\n", c.name, estimate.particles, placed,
               100.0 * (estimate.particles / placed - 1.0));
    CHECK(std::abs(estimate.particles / placed - 1.0) < 0.1);
    CHECK(estimate.fits());
  }
}

TEST_CASE("capacity: a refused project names the field and a value that fits", "[freezing][capacity]") {
  auto refused = [](const project::Project& p) {
    try {
      freezing::check_capacity(p, freezing::resolved_spacing(p));
    } catch (const project::ProjectError& e) {
      REQUIRE(e.problems().size() == 1);
      return e.problems().front();
    }
    return std::string();
  };
  const json limit = {{"numerics", {{"max_particles", 20000}}}};
  // The main job (about 6 700 particles) fits under 20 000; at 1 cm it
  // needs about four times as many and is refused, and the spacing
  // suggested then fits.
  CHECK(refused(test::shipped_project("single_ring_sand.json", limit)).empty());
  auto fine = limit;
  fine["numerics"]["spacing"] = 0.01;
  const std::string line = refused(test::shipped_project("single_ring_sand.json", fine));
  INFO(line);
  REQUIRE(line.starts_with("numerics.spacing: 0.01 m needs about "));
  const auto at = line.find("use a spacing of ") + 17;
  const double suggested = std::stod(line.substr(at));
  CHECK(suggested > 0.01);
  CHECK(suggested < 0.02);
  fine["numerics"]["spacing"] = suggested;
  CHECK(refused(test::shipped_project("single_ring_sand.json", fine)).empty());

  // A far field 300 m out at the default spacing: the domain is to blame,
  // and the radius suggested fits.
  auto far = limit;
  far["domain"] = {{"outer_radius", 300.0}};
  const std::string wide = refused(test::shipped_project("single_ring_sand.json", far));
  INFO(wide);
  REQUIRE(wide.starts_with("domain.outer_radius: 300 m needs about "));
  const double radius = std::stod(wide.substr(wide.find("use an outer radius of ") + 23));
  CHECK(radius >= 15.0);
  CHECK(radius < 300.0);
  far["domain"]["outer_radius"] = radius;
  CHECK(refused(test::shipped_project("single_ring_sand.json", far)).empty());
}
