// The report's 3-D view of the grains (report::render_grains): a sphere
// covers pi r^2 pixels at the scale the box fit sets, the nearer of two
// spheres hides the other whatever the drawing order, a cut-away removes
// the grains in front of the cut, and the lit side is the brighter.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "report/grain_render.hpp"

using namespace frostwall::report;

namespace {

using Rgb = std::array<std::uint8_t, 3>;
const std::array<double, 3> low{0, 0, 0}, high{1, 1, 1};

// Looking along -x at the unit cube, 208 px square with the 8 px margin:
// 192 px per metre, y to the right and z up.
GrainView side_view() {
  GrainView v;
  v.up_axis = 2, v.azimuth_deg = 0.0, v.elevation_deg = 0.0, v.width = 208, v.height = 208;
  return v;
}

int covered(const RgbaImage& im) {
  int n = 0;
  for (std::size_t k = 3; k < im.pixels.size(); k += 4) n += im.pixels[k] == 255;
  return n;
}

}  // namespace

TEST_CASE("A sphere covers pi r^2 pixels at the box's scale", "[cfd_dem][report][render]") {
  const auto im = render_grains({{0.5, 0.5, 0.5}}, {0.5}, {Rgb{200, 100, 50}}, low, high, side_view());
  const double r = 0.25 * 192.0;
  CHECK(covered(im) == Approx(std::numbers::pi * r * r).epsilon(0.01));
  // Centred: the picture's middle pixel is drawn, a corner is not.
  CHECK(const_cast<RgbaImage&>(im).at(104, 104)[3] == 255);
  CHECK(const_cast<RgbaImage&>(im).at(5, 5)[3] == 0);
}

TEST_CASE("The nearer grain hides the farther whatever the order", "[cfd_dem][report][render]") {
  // The camera sits on +x: the grain at x = 0.8 is the nearer.
  const Rgb red{250, 0, 0}, blue{0, 0, 250};
  for (bool near_first : {true, false}) {
    std::vector<std::array<double, 3>> c = {{0.8, 0.5, 0.5}, {0.2, 0.5, 0.5}};
    std::vector<Rgb> colour = {red, blue};
    if (!near_first) std::swap(c[0], c[1]), std::swap(colour[0], colour[1]);
    auto im = render_grains(c, {0.3, 0.3}, colour, low, high, side_view());
    CHECK(int(im.at(104, 104)[0]) > 0);
    CHECK(int(im.at(104, 104)[2]) == 0);
    // Seen from -x instead, the grain at x = 0.2 is in front; cutting away
    // x < 0.5 shows the one behind it again.
    GrainView back = side_view();
    back.azimuth_deg = 180.0;
    CHECK(int(render_grains(c, {0.3, 0.3}, colour, low, high, back).at(104, 104)[2]) > 0);
    back.cut_axis = 0, back.cut_at = 0.5;
    auto behind = render_grains(c, {0.3, 0.3}, colour, low, high, back);
    CHECK(int(behind.at(104, 104)[0]) > 0);
    CHECK(int(behind.at(104, 104)[2]) == 0);
  }
}

TEST_CASE("The lit side of a grain is the brighter and no pixel exceeds its colour", "[cfd_dem][report][render]") {
  auto im = render_grains({{0.5, 0.5, 0.5}}, {0.5}, {Rgb{200, 200, 200}}, low, high, side_view());
  // The light comes from the upper left: compare points 30 px from the centre.
  CHECK(int(im.at(104 - 21, 104 - 21)[0]) > int(im.at(104 + 21, 104 + 21)[0]));
  int brightest = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) brightest = std::max(brightest, int(im.at(x, y)[0]));
  CHECK(brightest <= 200);
  CHECK(brightest >= 190);
}

TEST_CASE("Mismatched grain arrays are refused", "[cfd_dem][report][render]") {
  CHECK_THROWS(render_grains({{0.5, 0.5, 0.5}}, {}, {Rgb{1, 1, 1}}, low, high, side_view()));
}
