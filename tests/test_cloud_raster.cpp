// Story: a plate's temperature map shows what ParaView shows of the VTK
// cells, the field linear over the particles' triangles, read from the
// snapshots' point data whatever cells they carry. A linear field is
// reproduced exactly at every pixel (barycentric weights sum to one and
// reproduce x and y), pixels beyond the cloud and inside a hole stay
// transparent, and the pixels inside cover the cloud's area.
#include <catch2/catch.hpp>
#include <cmath>

#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "geometry/cloud_mesh.hpp"
#include "report/cloud_raster.hpp"
#include "report/run_files.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using Vec2 = particles::Vec<2>;

TEST_CASE("A cloud raster reproduces a linear field and leaves holes and the outside blank", "[shared][report][map]") {
  // A 20 x 20 lattice of spacing 0.05 (centres 0.025 .. 0.975), a disc of
  // radius 0.2 at (0.5, 0.5) left empty: a hole.
  const double s = 0.05;
  std::vector<Vec2> points;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const Vec2 x((i + 0.5) * s, (j + 0.5) * s);
      if ((x - Vec2(0.5, 0.5)).norm() > 0.2) points.push_back(x);
    }
  auto linear = [](const Vec2& x) { return 3.0 - 2.0 * x[0] + 5.0 * x[1]; };
  std::vector<double> values;
  for (const auto& x : points) values.push_back(linear(x));

  report::MapWindow window;
  window.x0 = window.y0 = -0.25;  // the cloud sits in the middle of a 1.5 m window
  window.size = 1.5;
  window.pixels = 150;
  const report::CloudRaster raster(points, 2.5 * s, window);
  REQUIRE(raster.triangles() > 0);
  const auto v = raster.sample(values);
  REQUIRE(v.size() == 150u * 150u);
  const double d = window.size / window.pixels;
  std::size_t inside = 0, wrong = 0, in_hole = 0, outside_cloud = 0;
  for (int row = 0; row < window.pixels; ++row)
    for (int col = 0; col < window.pixels; ++col) {
      const double value = v[std::size_t(row) * window.pixels + col];
      const Vec2 x(window.x0 + (col + 0.5) * d, window.y0 + window.size - (row + 0.5) * d);
      if (!std::isfinite(value)) continue;
      ++inside;
      wrong += std::abs(value - linear(x)) > 1e-9;
      in_hole += (x - Vec2(0.5, 0.5)).norm() < 0.2 - 1.5 * s;  // well inside the hole
      outside_cloud += x[0] < 0.025 - 1e-9 || x[0] > 0.975 + 1e-9 || x[1] < 0.025 - 1e-9 || x[1] > 0.975 + 1e-9;
    }
  CHECK(wrong == 0);
  CHECK(in_hole == 0);
  CHECK(outside_cloud == 0);
  // The covered area: the lattice's hull (0.95 x 0.95) less about the hole (radius 0.2 less up to a spacing).
  const double area = inside * d * d, hull = 0.95 * 0.95;
  CHECK(area < hull - M_PI * 0.15 * 0.15);
  CHECK(area > hull - M_PI * 0.2 * 0.2 - 0.02);

  // Painted where sampled, transparent elsewhere.
  const report::ColourScale colours(0.0, 10.0, 5.0);
  const auto image = raster.raster(values, colours);
  std::size_t opaque = 0;
  for (std::size_t k = 3; k < image.pixels.size(); k += 4) opaque += image.pixels[k] == 255;
  CHECK(opaque == inside);
}

// The maps read the particles' point data whatever cells a .vtu carries
// (vertices or the particles' triangles): a file of triangle cells gives
// back every point with its fields, and the solid's free particles only.
TEST_CASE("The report reads a .vtu's points and fields whatever its cells", "[shared][report][map]") {
  const test::TempDir dir("frostwall-vtu-cells");
  const std::vector<Vec2> points{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {2.0, 2.0}};
  const std::vector<double> boundary{-1, -1, -1, -1, 0};  // the last one held (a fixed particle)
  vtkNew<vtkPoints> xyz;
  for (const auto& x : points) xyz->InsertNextPoint(x[0], x[1], 0.0);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(xyz);
  for (const auto& t : geometry::cloud_triangles(points)) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
  }
  REQUIRE(grid->GetNumberOfCells() > 0);
  auto field = [&](const char* name, int components, auto&& value) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    for (std::size_t i = 0; i < points.size(); ++i)
      for (int c = 0; c < components; ++c) a->InsertNextValue(value(i, c));
    grid->GetPointData()->AddArray(a);
  };
  field("temperature", 1, [](std::size_t i, int) { return 10.0 * i; });
  field("volume", 1, [](std::size_t, int) { return 1.0; });
  field("boundary", 1, [&](std::size_t i, int) { return boundary[i]; });
  field("damage", 1, [](std::size_t i, int) { return 0.1 * i; });
  field("displacement", 3, [](std::size_t i, int c) { return c == 0 ? 3.0 * i : (c == 1 ? 4.0 * i : 0.0); });
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  const auto file = dir.path / "field_0001.vtu";
  writer->SetFileName(file.c_str());
  writer->SetInputData(grid);
  REQUIRE(writer->Write() == 1);

  const auto f = report::read_field(file);
  REQUIRE(f.position.size() == points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    CHECK((f.position[i] - points[i]).norm() == Approx(0.0).margin(1e-12));
    CHECK(f.temperature[i] == Approx(10.0 * i));
    CHECK(f.boundary[i] == int(boundary[i]));
  }
  const auto s = report::read_solid(file);
  REQUIRE(s.particles.position.size() == 4);  // the free ones
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(s.particles.temperature[i] == Approx(5.0 * i));  // |displacement| of (3i, 4i)
    CHECK(s.damage[i] == Approx(0.1 * i));
    CHECK(s.temperature[i] == Approx(10.0 * i));
  }
}
