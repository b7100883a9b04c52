#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "particles/mirror_images.hpp"
#include "io/polyline_vtk.hpp"
#include "post/isoline.hpp"
#include "sph/laplacian.hpp"
#include "particles/particle_set.hpp"
#include "temp_dir.hpp"

namespace fs = std::filesystem;
using frostwall::post::isolines;
using frostwall::post::Polyline;
using Vec2 = frostwall::particles::Vec<2>;

namespace {

// Square lattice i*d, j*d covering [x0, x1] x [y0, y1] (integer multiples,
// so lattice values of a linear field are exact where d is a power of 2).
std::vector<Vec2> lattice(double x0, double x1, double y0, double y1, double d) {
  std::vector<Vec2> p;
  for (long i = std::lround(std::ceil(x0 / d)); i * d <= x1; ++i)
    for (long j = std::lround(std::ceil(y0 / d)); j * d <= y1; ++j) p.emplace_back(i * d, j * d);
  return p;
}

std::vector<double> sample(const std::vector<Vec2>& p, const std::function<double(const Vec2&)>& f) {
  std::vector<double> v;
  v.reserve(p.size());
  for (const auto& x : p) v.push_back(f(x));
  return v;
}

double max_radius_error(const Polyline& line, const Vec2& c, double R) {
  double e = 0.0;
  for (const auto& x : line.points) e = std::max(e, std::abs((x - c).norm() - R));
  return e;
}

// Shoelace area; positive for counterclockwise.
double signed_area(const Polyline& line) {
  double a = 0.0;
  for (std::size_t k = 0; k < line.points.size(); ++k) {
    const auto& p = line.points[k];
    const auto& q = line.points[(k + 1) % line.points.size()];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

// The linear interpolant of r = |x - c| along an edge of length l is above
// r by at most l^2/8 max r'' with r'' <= 1/r, and r >= R - l near the
// crossing; lattice Delaunay edges are at most sqrt(2) d long.
double circle_bound(double d, double R) {
  const double l = std::sqrt(2.0) * d;
  return l * l / (8.0 * (R - l));
}

// Keeps the parts of the lines on the side (x - p).n >= 0, cut exactly at
// the line; a closed line cut open starts at its first re-entry.
std::vector<Polyline> clip(const std::vector<Polyline>& lines, const Vec2& p, const Vec2& n) {
  std::vector<Polyline> out;
  auto side = [&](const Vec2& x) { return (x - p).dot(n); };
  for (const auto& line : lines) {
    std::vector<Vec2> pts = line.points;
    auto outside = std::find_if(pts.begin(), pts.end(), [&](const Vec2& x) { return side(x) < 0.0; });
    if (outside == pts.end()) {
      out.push_back(line);
      continue;
    }
    if (line.closed) {
      std::rotate(pts.begin(), outside, pts.end());
      pts.push_back(pts.front());
    }
    Polyline cur;
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const double sa = side(pts[k]);
      if (sa >= 0.0) cur.points.push_back(pts[k]);
      if (k + 1 == pts.size()) break;
      const double sb = side(pts[k + 1]);
      if ((sa >= 0.0) == (sb >= 0.0)) continue;
      cur.points.push_back(pts[k] + sa / (sa - sb) * (pts[k + 1] - pts[k]));
      if (sa >= 0.0) {  // leaving
        out.push_back(cur);
        cur.points.clear();
      }
    }
    if (cur.points.size() >= 2) out.push_back(cur);
  }
  return out;
}

}  // namespace

TEST_CASE("isoline of a circle: one closed counterclockwise curve, O(d^2) error", "[shared][isoline]") {
  const Vec2 c(0.0123, -0.0071);  // off the lattice, so no symmetric ties
  const double R = 1.0;
  std::vector<double> errors;
  for (double d : {0.1, 0.05, 0.025}) {
    const auto p = lattice(-1.6, 1.6, -1.6, 1.6, d);
    const auto lines = isolines(p, sample(p, [&](const Vec2& x) { return (x - c).norm() / R; }), 1.0);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].closed);
    CHECK(lines[0].points.size() > 2 * std::numbers::pi * R / d);  // at least one crossing per spacing
    const double e = max_radius_error(lines[0], c, R);
    CHECK(e <= circle_bound(d, R));
    // r is convex, so its interpolant overestimates: crossings lie inside.
    for (const auto& x : lines[0].points) CHECK((x - c).norm() <= R + 1e-12);
    // The region below level (inside) is on the left: counterclockwise.
    CHECK(signed_area(lines[0]) == Approx(std::numbers::pi * R * R).epsilon(d * d));
    errors.push_back(e);
    INFO("d = " << d << "  max |r - R| = " << e << " = " << e / d << " d, bound " << circle_bound(d, R));
    CHECK(e > 0.0);
  }
  INFO("max |r - R|: " << errors[0] << ", " << errors[1] << ", " << errors[2] << "; ratios " << errors[0] / errors[1]
                       << ", " << errors[1] / errors[2]);
  CHECK(errors[0] / errors[1] == Approx(4.0).margin(0.8));
  CHECK(errors[1] / errors[2] == Approx(4.0).margin(0.8));
}

TEST_CASE("isoline of a linear field is exact and open", "[shared][isoline]") {
  const double L = 2.0, level = 0.37, d = 0.1;
  const auto p = lattice(0.0, 1.0, 0.0, 1.0, d);
  const auto lines = isolines(p, sample(p, [&](const Vec2& x) { return x[0] / L; }), level);
  REQUIRE(lines.size() == 1);
  CHECK_FALSE(lines[0].closed);
  for (const auto& x : lines[0].points) CHECK(x[0] == Approx(L * level).margin(1e-12));
  // From hull to hull; below (x < L level) on the left means heading +y.
  CHECK(lines[0].points.front()[1] == Approx(0.0).margin(1e-12));
  CHECK(lines[0].points.back()[1] == Approx(1.0).margin(1e-12));
}

TEST_CASE("isoline through lattice values equal to the level", "[shared][isoline]") {
  // d = 1/8: lattice values are exact, so a whole column sits at the level.
  const double d = 0.125;
  const auto p = lattice(0.0, 1.0, 0.0, 1.0, d);
  const auto lines = isolines(p, sample(p, [](const Vec2& x) { return x[0]; }), 0.5);
  REQUIRE(lines.size() == 1);
  CHECK_FALSE(lines[0].closed);
  // Values at the level count as above: the front runs along that column,
  // one point per particle, with no repeated points.
  CHECK(lines[0].points.size() == 9);
  for (const auto& x : lines[0].points) CHECK(x[0] == 0.5);
  for (std::size_t k = 1; k < lines[0].points.size(); ++k) CHECK(lines[0].points[k][1] > lines[0].points[k - 1][1]);

  // A single particle exactly at level in a field below it: a region above
  // of zero area, no curve.
  std::vector<double> v(p.size(), 0.0);
  v[40] = 1.0;  // the particle at (0.5, 0.5)
  CHECK(isolines(p, v, 1.0).empty());
  const auto loop = isolines(p, v, 0.5);
  REQUIRE(loop.size() == 1);
  CHECK(loop[0].closed);
}

TEST_CASE("isolines of two circles are two closed curves", "[shared][isoline]") {
  const Vec2 c1(-1.2, 0.03), c2(1.3, -0.02);
  const double R = 0.8, d = 0.05;
  const auto p = lattice(-2.5, 2.5, -1.5, 1.5, d);
  const auto lines =
      isolines(p, sample(p, [&](const Vec2& x) { return std::min((x - c1).norm(), (x - c2).norm()) / R; }), 1.0);
  REQUIRE(lines.size() == 2);
  for (const auto& line : lines) {
    CHECK(line.closed);
    CHECK(signed_area(line) > 0.0);
    const Vec2& c = line.points[0][0] < 0.0 ? c1 : c2;
    CHECK(max_radius_error(line, c, R) <= circle_bound(d, R));
  }
  CHECK((lines[0].points[0][0] < 0.0) != (lines[1].points[0][0] < 0.0));
}

TEST_CASE("isoline: max_edge keeps the front out of a hole without particles", "[shared][isoline]") {
  // A pipe disc with no particles inside: Delaunay fills it with long
  // triangles, which would carry the front straight across.
  const double d = 0.1;
  const Vec2 hole(1.0, 1.0);
  std::vector<Vec2> p;
  for (const auto& x : lattice(0.0, 2.0, 0.0, 2.0, d))
    if ((x - hole).norm() > 0.35) p.push_back(x);
  const auto v = sample(p, [](const Vec2& x) { return x[1]; });
  const auto across = isolines(p, v, 1.03);
  REQUIRE(across.size() == 1);
  for (const auto& x : across[0].points) CHECK(x[1] == Approx(1.03).margin(1e-12));

  const auto split = isolines(p, v, 1.03, 3.0 * d);
  REQUIRE(split.size() == 2);
  for (const auto& line : split) {
    CHECK_FALSE(line.closed);
    for (std::size_t k = 1; k < line.points.size(); ++k) CHECK((line.points[k] - line.points[k - 1]).norm() <= 3.0 * d);
  }
  CHECK_THROWS_AS(isolines(p, v, 1.03, 0.0), std::invalid_argument);
  CHECK_THROWS_AS(isolines(p, std::vector<double>(3, 0.0), 1.03), std::invalid_argument);
}

TEST_CASE("write_vtp: polylines read back, closed ones repeat their first id", "[shared][isoline]") {
  frostwall::test::TempDir dir("frostwall-isoline");
  const Vec2 c1(-1.2, 0.03), c2(1.3, -0.02);
  const auto p = lattice(-2.5, 2.5, -1.5, 1.5, 0.1);
  auto lines =
      isolines(p, sample(p, [&](const Vec2& x) { return std::min((x - c1).norm(), (x - c2).norm()) / 0.8; }), 1.0);
  REQUIRE(lines.size() == 2);
  lines.push_back({{Vec2(0.0, 0.0), Vec2(0.5, 0.25), Vec2(1.0, -0.125)}, false});

  const fs::path file = dir.path / "interface_0010.vtp";
  frostwall::io::write_vtp(file, lines);
  for (const auto& entry : fs::directory_iterator(dir.path))
    CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);

  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  std::size_t n_points = 0;
  for (const auto& line : lines) n_points += line.points.size();
  REQUIRE(data->GetNumberOfPoints() == static_cast<vtkIdType>(n_points));
  REQUIRE(data->GetNumberOfLines() == static_cast<vtkIdType>(lines.size()));
  REQUIRE(data->GetNumberOfCells() == static_cast<vtkIdType>(lines.size()));
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    const auto& line = lines[static_cast<std::size_t>(c)];
    CHECK(data->GetCellType(c) == VTK_POLY_LINE);
    vtkNew<vtkIdList> ids;
    data->GetCellPoints(c, ids);
    REQUIRE(ids->GetNumberOfIds() == static_cast<vtkIdType>(line.points.size() + (line.closed ? 1 : 0)));
    if (line.closed) CHECK(ids->GetId(ids->GetNumberOfIds() - 1) == ids->GetId(0));
    for (std::size_t k = 0; k < line.points.size(); ++k) {
      double x[3];
      data->GetPoint(ids->GetId(static_cast<vtkIdType>(k)), x);
      CHECK(x[0] == line.points[k][0]);
      CHECK(x[1] == line.points[k][1]);
      CHECK(x[2] == 0.0);
    }
  }

  // Before anything freezes there is no front: still a valid (empty) file.
  const fs::path empty = dir.path / "interface_0000.vtp";
  frostwall::io::write_vtp(empty, {});
  vtkNew<vtkXMLPolyDataReader> empty_reader;
  empty_reader->SetFileName(empty.string().c_str());
  empty_reader->Update();
  CHECK(empty_reader->GetOutput()->GetNumberOfPoints() == 0);
  CHECK(empty_reader->GetOutput()->GetNumberOfLines() == 0);

  // A write that cannot happen throws (VTK's own error print silenced).
  const bool warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  CHECK_THROWS_AS(frostwall::io::write_vtp(dir.path / "missing" / "x.vtp", lines), std::runtime_error);
  vtkObject::SetGlobalWarningDisplay(warnings);
}

TEST_CASE("isoline with mirror images reaches the symmetry plane", "[shared][isoline]") {
  // A 30 deg wedge (planes y = 0 and theta = 30 deg through the origin) and
  // a circle centred on the 30 deg plane, which the lattice does not follow:
  // with the images (carrying their source's value) the front crosses the
  // plane into the strip of images, and clipped to the wedge it is a half
  // circle ending exactly on the plane.
  using frostwall::particles::MirrorPlane;
  const double d = 0.05, R = 0.5, angle = std::numbers::pi / 6.0;
  const Vec2 e30(std::cos(angle), std::sin(angle));
  const Vec2 c = 2.0 * e30;
  const Vec2 n30(-std::sin(angle), std::cos(angle));  // out of the wedge
  frostwall::particles::ParticleSet<2> particles;
  particles.spacing = d;
  particles.mirrors = {MirrorPlane<2>{Vec2::Zero(), Vec2(0.0, 1.0)}, MirrorPlane<2>{Vec2::Zero(), n30}};
  for (const auto& x : lattice(0.0, 3.5, 0.0, 3.5, d))
    if (x.norm() <= 3.5 && x.dot(n30) <= 0.0) particles.add(x, d * d, -1);
  particles.order_free_first();

  auto field = [&](const Vec2& x) { return (x - c).norm() / R; };
  const auto values = sample(particles.position, field);
  const auto bare = isolines(particles.position, values, 1.0, 3.0 * d);
  REQUIRE(bare.size() == 1);
  CHECK_FALSE(bare[0].closed);
  // The wedge alone stops short of the plane (its hull is the jagged row of
  // lattice points inside it).
  CHECK(bare[0].points.front().dot(n30) < -1e-3 * d);
  CHECK(bare[0].points.back().dot(n30) < -1e-3 * d);

  const auto images = frostwall::particles::mirror_images(particles, 3.0 * d);
  REQUIRE(!images.position.empty());
  auto points = particles.position;
  auto all_values = values;
  for (std::size_t k = 0; k < images.position.size(); ++k) {
    points.push_back(images.position[k]);
    all_values.push_back(values[images.source[k]]);
  }
  const auto mirrored = isolines(points, all_values, 1.0, 3.0 * d);
  // Images exist only within reach of the wedge, so the front runs on
  // across the plane until the strip of images ends: open.
  REQUIRE(mirrored.size() == 1);
  CHECK_FALSE(mirrored[0].closed);

  const auto arc = clip(clip(mirrored, Vec2::Zero(), -n30), Vec2::Zero(), Vec2(0.0, 1.0));
  REQUIRE(arc.size() == 1);
  const auto& a = arc[0].points;
  CHECK(max_radius_error(arc[0], c, R) <= circle_bound(d, R));
  // Both ends on the plane, at either end of the diameter along it.
  CHECK(a.front().dot(n30) == Approx(0.0).margin(1e-12));
  CHECK(a.back().dot(n30) == Approx(0.0).margin(1e-12));
  const double s0 = (a.front() - c).dot(e30), s1 = (a.back() - c).dot(e30);
  CHECK(std::abs(s0 + s1) < 2.0 * circle_bound(d, R));
  CHECK(std::abs(s0 - s1) == Approx(2.0 * R).margin(2.0 * circle_bound(d, R)));
}
