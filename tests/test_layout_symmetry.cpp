// Pipe layouts: where the pattern puts the pipes, which layouts are input
// errors, and the mirror symmetry (wedge) found from the positions alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>
#include <vector>

#include "geometry/layout.hpp"
#include "geometry/symmetry.hpp"
#include "project/project.hpp"
#include "paths.hpp"

namespace fs = std::filesystem;
using namespace frostwall;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using geometry::Pipe2;
using project::Layout;
using project::Pattern;
using project::Ring;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

Layout ring_pattern(Pattern pattern, double radius, int count, double start_deg, double inner_radius = 0.0) {
  Layout layout;
  layout.pattern = pattern;
  layout.outer_ring = {radius, count, start_deg};
  if (inner_radius > 0) layout.inner_ring_radius = inner_radius;
  return layout;
}

Layout free_rings(std::vector<Ring> rings) {
  Layout layout;
  layout.pattern = Pattern::rings;
  layout.rings = std::move(rings);
  return layout;
}

Layout measured(std::vector<project::PipePosition> pipes) {
  Layout layout;
  layout.pattern = Pattern::pipes;
  layout.pipes = std::move(pipes);
  return layout;
}

project::ShaftSection section(Layout layout, double outer_radius = 15.0) {
  project::ShaftSection s;
  s.layout = std::move(layout);
  s.pipe.diameter = 0.127;
  s.pipe.model = project::PipeModel::disc;
  s.outer_radius = outer_radius;
  return s;
}

double angle_of(const Pipe2& p) { return std::atan2(p.y, p.x); }
double radius_of(const Pipe2& p) { return std::hypot(p.x, p.y); }

// Angle difference folded into [-pi, pi), for comparing rays.
double ray_difference(double a, double b) { return std::remainder(a - b, 2 * pi); }

bool pipe_on_ray(const std::vector<Pipe2>& pipes, double ray) {
  for (const auto& p : pipes)
    if (std::abs(ray_difference(angle_of(p), ray)) < 1e-9) return true;
  return false;
}

const fs::path valid_dir = fs::path(FROSTWALL_SOURCE_DIR) / "tests" / "data" / "valid";

}  // namespace

// ---- pipe positions ------------------------------------------------------------

TEST_CASE("single ring: count pipes from the start angle, counter-clockwise", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 26, 10.0));
  REQUIRE(pipes.size() == 26);
  CHECK(pipes[0].x == Approx(5.0 * std::cos(10 * deg)));
  CHECK(pipes[0].y == Approx(5.0 * std::sin(10 * deg)));
  CHECK(angle_of(pipes[1]) == Approx((10 + 360.0 / 26) * deg));
  CHECK(angle_of(pipes[13]) == Approx((10 + 180.0 - 360) * deg));  // opposite pipe 0
  for (const auto& p : pipes) CHECK(radius_of(p) == Approx(5.0));
  CHECK(pipes[3].ring == 0);
  CHECK(pipes[3].index == 3);
  CHECK(pipes[3].label == "outer 3");
}

TEST_CASE("three-hole: inner ring has the outer count, half a spacing on", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::three_hole, 5.0, 26, 10.0, 4.2));
  REQUIRE(pipes.size() == 52);
  const Pipe2& inner0 = pipes[26];
  CHECK(inner0.ring == 1);
  CHECK(inner0.label == "inner 0");
  CHECK(radius_of(inner0) == Approx(4.2));
  CHECK(angle_of(inner0) == Approx((10 + 180.0 / 26) * deg));
  CHECK(angle_of(pipes[27]) == Approx((10 + 180.0 / 26 + 360.0 / 26) * deg));
}

TEST_CASE("four-hole: inner ring has twice the outer count, on and between outer angles", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::four_hole, 5.0, 26, 10.0, 4.2));
  REQUIRE(pipes.size() == 78);
  CHECK(pipes[26].label == "inner 0");
  CHECK(angle_of(pipes[26]) == Approx(10 * deg));                 // at outer pipe 0's angle
  CHECK(angle_of(pipes[27]) == Approx((10 + 180.0 / 26) * deg));  // halfway to outer pipe 1
  CHECK(angle_of(pipes[28]) == Approx(angle_of(pipes[1])));       // at outer pipe 1's angle
  CHECK(radius_of(pipes[77]) == Approx(4.2));
  CHECK(pipes[77].label == "inner 51");
}

TEST_CASE("rings and measured pipes as given", "[freezing][geometry]") {
  const auto rings = geometry::pipe_positions(free_rings({{5.0, 24, 0.0}, {6.0, 36, 5.0}}));
  REQUIRE(rings.size() == 60);
  CHECK(rings[24].ring == 1);
  CHECK(rings[24].label == "ring 1 pipe 0");
  CHECK(radius_of(rings[24]) == Approx(6.0));
  CHECK(angle_of(rings[24]) == Approx(5 * deg));
  CHECK(angle_of(rings[25]) == Approx(15 * deg));

  const auto pipes = geometry::pipe_positions(measured({{4.98, 0.31}, {-0.2, 5.03}, {-5.01, -0.1}}));
  REQUIRE(pipes.size() == 3);
  CHECK(pipes[2].x == -5.01);
  CHECK(pipes[2].y == -0.1);
  CHECK(pipes[2].ring == -1);
  CHECK(pipes[2].label == "pipe 2");
}

// ---- layout problems ---------------------------------------------------------

TEST_CASE("layout problems: overlapping pipes", "[freezing][geometry]") {
  SECTION("26 pipes on a 0.3 m ring: one line for the ring") {
    const auto problems = geometry::layout_problems(section(ring_pattern(Pattern::single, 0.3, 26, 0.0), 2.0));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "layout.outer_ring: 26 pipes on radius 0.300 m overlap their neighbours "
                         "(centres 0.072 m apart, pipe diameter 0.127 m)");
  }
  SECTION("four-hole inner ring 5 cm inside the outer one") {
    const auto problems = geometry::layout_problems(section(ring_pattern(Pattern::four_hole, 5.0, 26, 0.0, 4.95)));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "layout.inner_ring.radius: inner-ring pipes overlap the outer ring's "
                         "(closest centres 0.050 m apart, pipe diameter 0.127 m)");
  }
  SECTION("free rings") {
    const auto problems = geometry::layout_problems(section(free_rings({{5.0, 26, 0.0}, {5.05, 26, 0.0}})));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "layout.rings[1]: pipes overlap those of layout.rings[0] "
                         "(closest centres 0.050 m apart, pipe diameter 0.127 m)");
  }
  SECTION("measured pipes: one line per pair") {
    std::vector<project::PipePosition> p;
    for (int k = 0; k < 8; ++k) p.push_back({5.0 * std::cos(k * pi / 4), 5.0 * std::sin(k * pi / 4)});
    p[7] = {p[3].x + 0.08, p[3].y};
    const auto problems = geometry::layout_problems(section(measured(p)));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "layout.pipes[3]: overlaps layout.pipes[7] (centres 0.080 m apart, pipe diameter 0.127 m)");
  }
}

TEST_CASE("layout problems: excavation and far field", "[freezing][geometry]") {
  const Layout ring = ring_pattern(Pattern::single, 5.0, 26, 0.0);
  SECTION("pipe discs reaching into the excavation") {
    auto s = section(ring);
    s.shaft.excavation_radius = 4.95;
    const auto problems = geometry::layout_problems(s);
    REQUIRE(problems.size() == 1);
    CHECK_THAT(problems[0], StartsWith("layout.outer_ring.radius: outer-ring pipes reach into the excavation"));
    CHECK_THAT(problems[0], Contains("shaft.excavation_radius 4.950 m"));

    auto m = section(measured({{5.0, 0.0}, {0.0, 4.0}, {-5.0, 0.0}}));
    m.shaft.excavation_radius = 4.0;
    const auto measured_problems = geometry::layout_problems(m);
    REQUIRE(measured_problems.size() == 1);
    CHECK_THAT(measured_problems[0], StartsWith("layout.pipes[1]: the pipe reaches into the excavation"));
  }
  SECTION("pipe discs outside the far-field circle") {
    const auto problems = geometry::layout_problems(section(ring, 5.05));
    REQUIRE(problems.size() == 1);
    CHECK_THAT(problems[0], StartsWith("domain.outer_radius: the far-field circle of 5.050 m cuts through pipe discs "
                                       "(the pipes of layout.outer_ring reaching"));
    CHECK_THAT(problems[0], Contains("at least 5.31"));  // 5 + 0.127/2 + 2 * 0.127 = 5.3175
  }
  SECTION("far field too close for the disc model, fine for point pipes") {
    auto s = section(ring, 5.2);
    const auto problems = geometry::layout_problems(s);
    REQUIRE(problems.size() == 1);
    CHECK_THAT(problems[0], StartsWith("domain.outer_radius: the far-field circle of 5.200 m is only 0.13"));
    CHECK_THAT(problems[0], Contains("the disc model needs 2 pipe diameters (0.254 m)"));
    s.pipe.model = project::PipeModel::point;
    CHECK(geometry::layout_problems(s).empty());
  }
  SECTION("several problems in a fixed order: overlaps, excavation, far field") {
    auto s = section(ring_pattern(Pattern::four_hole, 5.0, 26, 0.0, 4.95), 5.1);
    s.shaft.excavation_radius = 4.9;
    const auto problems = geometry::layout_problems(s);
    REQUIRE(problems.size() == 3);
    CHECK_THAT(problems[0], StartsWith("layout.inner_ring.radius: inner-ring pipes overlap"));
    CHECK_THAT(problems[1], StartsWith("layout.inner_ring.radius: inner-ring pipes reach into the excavation"));
    CHECK_THAT(problems[2], StartsWith("domain.outer_radius:"));
    CHECK(geometry::layout_problems(s) == problems);
  }
}

TEST_CASE("layout problems: the shipped layouts have none", "[freezing][geometry]") {
  int shaft_sections = 0;
  for (const auto& entry : fs::directory_iterator(valid_dir)) {
    const auto project = project::load_project(entry.path().string());
    if (const auto* s = std::get_if<project::ShaftSection>(&project.geometry)) {
      INFO(entry.path().filename().string());
      CHECK(geometry::layout_problems(*s).empty());
      ++shaft_sections;
    }
  }
  CHECK(shaft_sections >= 4);
}

// ---- symmetry ------------------------------------------------------------------

TEST_CASE("symmetry of a single ring of 26: 26 mirror lines from the start angle", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 26, 0.0));
  const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
  CHECK(w.mirror_count == 26);
  CHECK(w.angle == Approx(pi / 26));
  CHECK(w.angle / deg == Approx(6.923).epsilon(1e-4));
  CHECK(w.start_angle == Approx(0.0).margin(1e-12));
  CHECK(geometry::describe(w) == "symmetry: 26 mirror lines, wedge of 6.923 deg from 0.000 deg");
}

TEST_CASE("symmetry of a ring rotated by an arbitrary start angle", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 26, 13.7));
  const auto w = geometry::find_symmetry_wedge(pipes, 13.7 * deg);
  CHECK(w.mirror_count == 26);
  CHECK(w.angle == Approx(pi / 26));
  CHECK(w.start_angle == Approx(13.7 * deg));
  CHECK(pipe_on_ray(pipes, w.start_angle));
}

TEST_CASE("symmetry of the double rings: the wedge of the outer ring", "[freezing][geometry]") {
  SECTION("three-hole: inner pipes on OB") {
    const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::three_hole, 5.0, 26, 0.0, 4.2));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 26);
    CHECK(w.angle == Approx(pi / 26));
    CHECK(w.start_angle == Approx(0.0).margin(1e-12));
    // OA through outer pipe 0, OB (the wedge's far side) through inner pipe 0.
    CHECK(angle_of(pipes[0]) == Approx(w.start_angle).margin(1e-12));
    CHECK(angle_of(pipes[26]) == Approx(w.start_angle + w.angle));
  }
  SECTION("four-hole") {
    const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::four_hole, 5.0, 26, 0.0, 4.2));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 26);
    CHECK(w.angle / deg == Approx(180.0 / 26));
    CHECK(w.start_angle == Approx(0.0).margin(1e-12));
  }
}

TEST_CASE("symmetry of rings with a common divisor: M = gcd of the counts", "[freezing][geometry]") {
  const auto pipes = geometry::pipe_positions(free_rings({{5.0, 24, 0.0}, {6.0, 36, 0.0}}));
  const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
  CHECK(w.mirror_count == 12);
  CHECK(w.angle / deg == Approx(15.0));
  CHECK(w.start_angle == Approx(0.0).margin(1e-12));
  CHECK(geometry::mirror_lines(pipes, geometry::default_symmetry_tolerance(pipes)).size() == 12);
}

TEST_CASE("symmetry of an odd ring: OA on the pipe, not on the gap opposite", "[freezing][geometry]") {
  SECTION("start 0") {
    const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 5, 0.0));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 5);
    CHECK(w.angle / deg == Approx(36.0));
    CHECK(w.start_angle == Approx(0.0).margin(1e-12));
    CHECK(pipe_on_ray(pipes, w.start_angle));
  }
  SECTION("start 180 deg: the line through the pipe also runs through the gap at 0") {
    const auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 5, 180.0));
    const auto w = geometry::find_symmetry_wedge(pipes, pi);
    CHECK(w.mirror_count == 5);
    CHECK(w.start_angle == Approx(pi));
    CHECK(pipe_on_ray(pipes, w.start_angle));
    CHECK_FALSE(pipe_on_ray(pipes, 0.0));
  }
}

TEST_CASE("symmetry of a ring with one pipe 5 cm off", "[freezing][geometry]") {
  auto pipes = geometry::pipe_positions(ring_pattern(Pattern::single, 5.0, 26, 0.0));
  const double theta = angle_of(pipes[3]);  // 41.5 deg
  SECTION("radially: only the line through that pipe survives") {
    pipes[3].x += 0.05 * std::cos(theta);
    pipes[3].y += 0.05 * std::sin(theta);
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 1);
    CHECK(w.angle == Approx(pi));
    // 0 is no longer on a mirror: the wedge starts on the first mirror ray
    // counter-clockwise, the one through the moved pipe.
    CHECK(w.start_angle == Approx(theta));
    CHECK(geometry::describe(w) == "symmetry: 1 mirror line, wedge of 180.000 deg from 41.538 deg");
  }
  SECTION("tangentially: no mirror left") {
    pipes[3].x -= 0.05 * std::sin(theta);
    pipes[3].y += 0.05 * std::cos(theta);
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 0);
    CHECK(w.angle == Approx(2 * pi));
    CHECK(w.start_angle == Approx(0.0).margin(1e-12));
    CHECK(geometry::describe(w) == "symmetry: no mirror line, full circle from 0.000 deg");
  }
}

TEST_CASE("symmetry of measured pipes comes from the positions", "[freezing][geometry]") {
  SECTION("the shipped survey with deviations: full circle") {
    const auto project = project::load_project((valid_dir / "measured_pipes.json").string());
    const auto pipes = geometry::pipe_positions(std::get<project::ShaftSection>(project.geometry).layout);
    REQUIRE(pipes.size() == 4);
    const auto w = geometry::find_symmetry_wedge(pipes, angle_of(pipes[0]));
    CHECK(w.mirror_count == 0);
    CHECK(w.angle == Approx(2 * pi));
  }
  SECTION("four pipes exactly on a square: 4 mirror lines, no pattern needed") {
    const auto pipes = geometry::pipe_positions(measured({{5.0, 0.0}, {0.0, 5.0}, {-5.0, 0.0}, {0.0, -5.0}}));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 4);
    CHECK(w.angle / deg == Approx(45.0));
  }
}

TEST_CASE("symmetry: rotational only is not used", "[freezing][geometry]") {
  SECTION("two 6-pipe rings 10 deg apart on different radii: M = 0") {
    const auto pipes = geometry::pipe_positions(free_rings({{5.0, 6, 0.0}, {6.0, 6, 10.0}}));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 0);
    CHECK(w.angle == Approx(2 * pi));
  }
  SECTION("the same rings on one radius are mirrored about the 5 deg bisectors") {
    const auto pipes = geometry::pipe_positions(free_rings({{5.0, 6, 0.0}, {5.0, 6, 10.0}}));
    const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
    CHECK(w.mirror_count == 6);
    CHECK(w.angle / deg == Approx(30.0));
    CHECK(w.start_angle / deg == Approx(5.0));
  }
}

TEST_CASE("symmetry of the shipped free rings: 26 and 30 pipes share the 0 and 90 deg lines", "[freezing][geometry]") {
  const auto project = project::load_project((valid_dir / "two_rings.json").string());
  const auto pipes = geometry::pipe_positions(std::get<project::ShaftSection>(project.geometry).layout);
  const auto w = geometry::find_symmetry_wedge(pipes, 0.0);
  CHECK(w.mirror_count == 2);
  CHECK(w.angle / deg == Approx(90.0));
  CHECK(w.start_angle == Approx(0.0).margin(1e-12));
}

TEST_CASE("Under seepage only the mirror line along the flow survives", "[freezing][layout][groundwater]") {
  // 26 pipes on a ring from 0 deg: mirror lines every 180/26 deg.
  std::vector<Pipe2> pipes;
  for (int k = 0; k < 26; ++k) pipes.push_back({std::cos(k * 2 * pi / 26), std::sin(k * 2 * pi / 26), 0, k});
  const double tol = geometry::default_symmetry_tolerance(pipes);
  std::string note;
  // Along x, through pipe 0: half the section, from the flow's direction.
  const auto along = geometry::find_flow_symmetry_wedge(pipes, 0.0, tol, note);
  CHECK(along.mirror_count == 1);
  CHECK(along.angle == Approx(pi));
  CHECK_THAT(note, Contains("half the section"));
  // Along a line between two pipes' mirror lines: nothing survives.
  const auto skew = geometry::find_flow_symmetry_wedge(pipes, 2.0 * deg, tol, note);
  CHECK(skew.mirror_count == 0);
  CHECK(skew.angle == Approx(2 * pi));
  CHECK_THAT(note, Contains("full circle"));
  // Along a mirror line between pipes (half a pitch) and against the flow: half again.
  CHECK(geometry::find_flow_symmetry_wedge(pipes, 180.0 / 26 * deg, tol, note).mirror_count == 1);
  CHECK(geometry::find_flow_symmetry_wedge(pipes, pi, tol, note).mirror_count == 1);
  // Three pipes (a triangle pointing along x): along x half, along y full.
  std::vector<Pipe2> three = {{1, 0, 0, 0},
                              {std::cos(2 * pi / 3), std::sin(2 * pi / 3), 0, 1},
                              {std::cos(4 * pi / 3), std::sin(4 * pi / 3), 0, 2}};
  const double tol3 = geometry::default_symmetry_tolerance(three);
  CHECK(geometry::find_flow_symmetry_wedge(three, 0.0, tol3, note).mirror_count == 1);
  CHECK(geometry::find_flow_symmetry_wedge(three, pi / 2, tol3, note).mirror_count == 0);
}
