// The flow arrows on the report's maps (report/flow_arrows.hpp): a field
// known everywhere in the upper half plane (the wedge of one mirror line
// along x) is drawn over the whole plane, the lower half mirrored: the
// flux (1, 0.5) reads (1, -0.5) below the line, and the longest arrow is
// 0.9 of the grid's step.
#include <catch2/catch.hpp>
#include <cmath>

#include "report/flow_arrows.hpp"

using namespace frostwall;

TEST_CASE("Flow arrows: the mirrored half of the section points the mirrored way", "[shared][groundwater][report]") {
  report::FieldSnapshot field;
  for (int a = -20; a <= 20; ++a)
    for (int b = 0; b <= 20; ++b) {
      field.position.emplace_back(0.1 * a, 0.1 * b);
      field.boundary.push_back(-1);
      field.volume.push_back(0.01);
      field.temperature.push_back(0.0);
      field.darcy_flux.emplace_back(1.0, 0.5);
    }
  report::WedgeSymmetry half;
  half.mirror_lines = 1;
  half.start = 0.0;
  half.angle = M_PI;
  report::MapWindow window;
  window.x0 = window.y0 = -1.8;
  window.size = 3.6;
  const auto arrows = report::flow_arrows(field, half, window, 0.0, 12);
  REQUIRE(arrows.size() == 144);
  const double step = window.size / 12, longest = 0.9 * step;
  int above = 0, below = 0;
  for (const auto& a : arrows) {
    CHECK(std::hypot(a.dx, a.dy) == Approx(longest));
    CHECK(a.dx / longest == Approx(1.0 / std::hypot(1.0, 0.5)));
    const double y = a.y + 0.5 * a.dy;  // the grid point (the arrow is centred on it)
    if (y > 0) {
      CHECK(a.dy > 0);
      ++above;
    } else {
      CHECK(a.dy < 0);
      ++below;
    }
  }
  CHECK(above == 72);
  CHECK(below == 72);
  // No flux in the snapshot, or more than one mirror line: no arrows.
  report::FieldSnapshot still = field;
  still.darcy_flux.clear();
  CHECK(report::flow_arrows(still, half, window, 0.0).empty());
  half.mirror_lines = 2;
  CHECK(report::flow_arrows(field, half, window, 0.0).empty());
}
