// Story: ground that does not start at one temperature (a frozen inclusion,
// a warm patch): domain.initial_zones. A unit square at 5 C holds a
// rectangle (its left half) at -5 C, over it a circle of radius 0.2 on the
// square's centre at -10 C, and a triangle in the right half at -2 C.
// References, independent of the loader and the model:
//  - each particle whose cell lies in one zone starts at the temperature of
//    the last zone holding it, by the test's own point-in-shape checks;
//  - the heat stored at t = 0 equals the zones' exact areas times their
//    enthalpies, within the sampling of the cells the outlines cut (2e-4
//    of the range);
//  - a later zone lies over an earlier one (the circle over the rectangle).
// And bad zones are refused naming their path, before any work.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "freezing/model.hpp"
#include "support.hpp"

using namespace frostwall;

TEST_CASE("Initial zones set the starting temperature, the later over the earlier", "[initial_zones]") {
  const std::string numerics = R"({ "spacing": 0.01, "placement": "lattice" })";
  const std::string text = R"({ "name": "zones", "geometry": { "type": "rectangle", "width": 1, "height": 1,
      "boundaries": { "left": "adiabatic", "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" } },
    "soil": )" + test::unit_soil(0.0, 50.0) +
                           R"(,
    "domain": { "initial_temperature": 5, "initial_zones": [
      { "rectangle": [0, 0, 0.5, 1], "temperature": -5 },
      { "circle": [0.5, 0.5, 0.2], "temperature": -10 },
      { "polygon": [[0.6, 0.1], [0.9, 0.1], [0.9, 0.3]], "temperature": -2 } ] },
    "time": { "end": 1, "unit": "s", "snapshots": [1] },
    "numerics": )" + numerics +
                           R"(, "output": { "directory": "unused" } })";
  const auto p = project::parse_project(text);
  REQUIRE(p.domain.initial_zones.size() == 3);
  auto m = freezing::build_model(p);
  const auto& P = m.particles();
  const auto& law = m.model->law();

  auto expected = [](double x, double y) {
    double T = 5.0;
    if (x <= 0.5) T = -5.0;
    if (std::hypot(x - 0.5, y - 0.5) <= 0.2) T = -10.0;
    // The triangle (0.6, 0.1), (0.9, 0.1), (0.9, 0.3): above its base, left of x = 0.9, below its hypotenuse.
    if (y >= 0.1 && x <= 0.9 && y <= 0.1 + (x - 0.6) * (0.2 / 0.3)) T = -2.0;
    return T;
  };
  // A particle whose cell (corners and centre) lies in one zone starts at
  // its temperature.
  std::size_t wrong = 0, whole = 0;
  const double half = 0.5 * std::sqrt(P.volume[0]) * (1 - 1e-9);
  for (std::size_t i = 0; i < m.model->free_count(); ++i) {
    const double x = P.position[i][0], y = P.position[i][1], T = expected(x, y);
    if (expected(x - half, y - half) != T || expected(x + half, y - half) != T || expected(x - half, y + half) != T ||
        expected(x + half, y + half) != T)
      continue;
    ++whole;
    wrong += std::abs(m.model->temperature()[i] - T) > 1e-12;
  }
  CHECK(whole > 9000);
  CHECK(wrong == 0);

  const double circle = std::numbers::pi * 0.04, triangle = 0.5 * 0.3 * 0.2;
  const double exact = law.enthalpy(-10.0) * circle + law.enthalpy(-5.0) * (0.5 - 0.5 * circle) +
                       law.enthalpy(-2.0) * triangle + law.enthalpy(5.0) * (0.5 - 0.5 * circle - triangle);
  const double range = law.enthalpy(5.0) - law.enthalpy(-10.0);
  fmt::print("\nInitial zones: stored heat {:.5f} against the exact areas' {:.5f} ({:.2e} of the range)\n",
             m.model->stored_heat(), exact, (m.model->stored_heat() - exact) / range);
  CHECK(std::abs(m.model->stored_heat() - exact) < 2e-4 * range);
}
