// Story: an engineer opens the main job's files in ParaView and draws the
// design isotherm with the Contour filter, with no preparation. The files
// are read back with VTK's own XML reader and contoured with VTK's own
// vtkContourFilter (what ParaView runs):
//  - the ring files hold triangles, none across a pipe disc;
//  - at day 10 (before closure) the -8 degC isotherm is a closed curve
//    around each pipe and none around the shaft; at day 60, once the wall
//    colder than -8 degC has closed too (the frozen wall closes at 13.9 d),
//    it is one closed curve on each side of the ring;
//  - no file holds a temperature outside what the pipes (-20 degC) and
//    the initial ground (15 degC) span: no antisymmetric ghost layer of
//    the pipe walls is written;
//  - every file names its project, time unit and frostwall version;
//  - open_in_paraview.py loads series that exist, with the colour map
//    spanning what the files hold, and is valid Python (when python3 is
//    there to parse it).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fmt/core.h>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkContourFilter.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"
#include "text_file.hpp"

using namespace frostwall;
namespace fs = std::filesystem;

namespace {

vtkSmartPointer<vtkUnstructuredGrid> read_grid(const fs::path& file) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  return grid;
}

std::string label(vtkUnstructuredGrid& grid, const char* name) {
  auto* array = vtkStringArray::SafeDownCast(grid.GetFieldData()->GetAbstractArray(name));
  return array && array->GetNumberOfValues() == 1 ? array->GetValue(0) : std::string("(none)");
}

// One closed curve of a contour: its radii from the shaft axis and how
// many times it winds around it.
struct Loop {
  double r_min = 1e300, r_max = 0.0;
  int winding = 0;
};

// The contour's line segments joined into curves; throws if a point ends
// or branches (not a closed curve).
std::vector<Loop> closed_loops(vtkPolyData& lines) {
  std::map<vtkIdType, std::vector<vtkIdType>> next;
  vtkNew<vtkIdList> ids;
  auto* cells = lines.GetLines();
  for (cells->InitTraversal(); cells->GetNextCell(ids);)
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k) {
      next[ids->GetId(k)].push_back(ids->GetId(k + 1));
      next[ids->GetId(k + 1)].push_back(ids->GetId(k));
    }
  std::vector<Loop> loops;
  std::set<vtkIdType> seen;
  for (const auto& [start, neighbours] : next) {
    if (seen.count(start)) continue;
    Loop loop;
    double turned = 0.0;
    vtkIdType previous = -1, at = start;
    do {
      if (next[at].size() != 2) throw std::runtime_error("the contour has an open end or a branch");
      seen.insert(at);
      const vtkIdType to = next[at][0] == previous ? next[at][1] : next[at][0];
      double a[3], b[3];
      lines.GetPoint(at, a);
      lines.GetPoint(to, b);
      const double r = std::hypot(a[0], a[1]);
      loop.r_min = std::min(loop.r_min, r), loop.r_max = std::max(loop.r_max, r);
      turned += std::remainder(std::atan2(b[1], b[0]) - std::atan2(a[1], a[0]), 2.0 * std::numbers::pi);
      previous = at;
      at = to;
    } while (at != start);
    loop.winding = static_cast<int>(std::lround(turned / (2.0 * std::numbers::pi)));
    loops.push_back(loop);
  }
  return loops;
}

std::vector<Loop> isotherm(vtkUnstructuredGrid& grid, double level) {
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(&grid);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "temperature");
  contour->SetValue(0, level);
  contour->Update();
  return closed_loops(*contour->GetOutput());
}

}  // namespace

TEST_CASE("ParaView's Contour filter draws the design isotherm on the main job's ring files",
          "[freezing][shaft][io][paraview]") {
  test::TempDir dir("frostwall-paraview");
  auto p = test::shipped_project("single_ring_sand.json",
                                 {{"time", {{"end", 60}, {"snapshots", {10, 60}}}}, {"output", {{"report", false}}}});
  p.output.directory = (dir.path / "out").string();
  run::run_project(p, {});
  const fs::path out = dir.path / "out";
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  const double closure = summary["closure_time_days"];
  REQUIRE(closure > 10.0);
  REQUIRE(closure < 60.0);

  const double ring_radius = 5.0, pipe_radius = 0.127 / 2, pipe_T = -20.0, ground_T = 15.0;
  for (const char* name : {"field_0010.vtu", "field_0060.vtu", "ring_0010.vtu", "ring_0060.vtu"}) {
    INFO(name);
    auto grid = read_grid(out / name);
    REQUIRE(grid->GetNumberOfPoints() > 0);
    CHECK(label(*grid, "project") == summary["project"].get<std::string>());
    CHECK(label(*grid, "time_unit") == "d");
    CHECK(label(*grid, "frostwall_version") == summary["frostwall_version"].get<std::string>());
    REQUIRE(grid->GetPointData()->GetArray("boundary") != nullptr);
    double range[2];
    grid->GetPointData()->GetArray("temperature")->GetRange(range);
    CHECK(range[0] >= pipe_T - 1e-6);
    CHECK(range[1] <= ground_T + 1e-6);
    // Triangles, and none lies across a pipe disc: no centroid inside one.
    vtkIdType triangles = 0, inside_pipe = 0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
      if (grid->GetCellType(c) != VTK_TRIANGLE) continue;
      ++triangles;
      double centre[2] = {0.0, 0.0}, x[3];
      auto* pts = grid->GetCell(c)->GetPointIds();
      for (int k = 0; k < 3; ++k) grid->GetPoint(pts->GetId(k), x), centre[0] += x[0] / 3, centre[1] += x[1] / 3;
      const double r = std::hypot(centre[0], centre[1]);
      const double angle = std::atan2(centre[1], centre[0]);
      const double pitch = 2.0 * std::numbers::pi / 26;
      const double nearest = std::round(angle / pitch) * pitch;  // pipes at 0, pitch, 2 pitch, ...
      const double d =
          std::hypot(centre[0] - ring_radius * std::cos(nearest), centre[1] - ring_radius * std::sin(nearest));
      inside_pipe += d < pipe_radius && r > 0.0;
    }
    CHECK(triangles > grid->GetNumberOfPoints());  // about two per point
    CHECK(inside_pipe == 0);
  }

  // The front curves name their project too.
  vtkNew<vtkXMLPolyDataReader> curves;
  curves->SetFileName((out / "interface_ring_0060.vtp").c_str());
  curves->Update();
  auto* project = vtkStringArray::SafeDownCast(curves->GetOutput()->GetFieldData()->GetAbstractArray("project"));
  REQUIRE(project != nullptr);
  CHECK(project->GetValue(0) == summary["project"].get<std::string>());

  // The ParaView script: the collections it opens exist, its temperature
  // range is what the files hold, and Python parses it.
  const std::string script = test::read_text(out / "open_in_paraview.py");
  for (const char* series : {"ring.pvd", "field.pvd"}) {
    CHECK(script.find(fmt::format("(\"{}\", 'temperature'", series)) != std::string::npos);
    CHECK(fs::exists(out / series));
  }
  CHECK(script.find("COLDEST = -20 ") != std::string::npos);
  CHECK(script.find("WARMEST = 15 ") != std::string::npos);
  if (std::system("python3 -c '' 2>/dev/null") == 0)
    CHECK(std::system(("python3 -c \"import ast,sys; ast.parse(open(sys.argv[1]).read())\" '" +
                       (out / "open_in_paraview.py").string() + "'")
                          .c_str()) == 0);
  else WARN("python3 is not installed: open_in_paraview.py not parsed");

  // Before closure (day 10): a closed isotherm around every pipe, none
  // around the shaft.
  const auto before = isotherm(*read_grid(out / "ring_0010.vtu"), -8.0);
  CHECK(before.size() == 26);
  for (const auto& loop : before) {
    CHECK(loop.winding == 0);
    CHECK(loop.r_min > ring_radius - 1.0);
    CHECK(loop.r_max < ring_radius + 1.0);
  }
  // Day 60: one closed curve inside the ring, one outside.
  const auto after = isotherm(*read_grid(out / "ring_0060.vtu"), -8.0);
  REQUIRE(after.size() == 2);
  const auto& inner = after[0].r_max < after[1].r_max ? after[0] : after[1];
  const auto& outer = after[0].r_max < after[1].r_max ? after[1] : after[0];
  CHECK(std::abs(inner.winding) == 1);
  CHECK(std::abs(outer.winding) == 1);
  CHECK(inner.r_max < ring_radius - pipe_radius);
  CHECK(outer.r_min > ring_radius + pipe_radius);
}

TEST_CASE(
    "A PD plate's files hold the plate alone, as triangles ParaView contours, within the boundary and start temperatures",
    "[pd][mechanics][io][paraview]") {
  test::TempDir dir("frostwall-paraview-plate");
  auto p =
      test::shipped_project("plate_cooling.json", {{"numerics", {{"method", "pd"}, {"spacing", 0.0005}}},
                                                   {"time", {{"end", 100}, {"unit", "s"}, {"snapshots", {25, 100}}}},
                                                   {"output", {{"report", false}}}});
  p.output.directory = (dir.path / "out").string();
  run::run_project(p, {});
  const fs::path out = dir.path / "out";
  const double side = 0.01, face_T = 1.0, start_T = 10.0;
  for (const char* name : {"field_0025.vtu", "field_0100.vtu"}) {
    INFO(name);
    auto grid = read_grid(out / name);
    REQUIRE(grid->GetNumberOfPoints() >= 20 * 20);
    REQUIRE(grid->GetPointData()->GetArray("displacement") != nullptr);
    double range[2], bounds[6];
    grid->GetPointData()->GetArray("temperature")->GetRange(range);
    CHECK(range[0] >= face_T - 1e-9);
    CHECK(range[1] <= start_T + 1e-9);
    // Every point on the plate (the cooled faces' own row included), none
    // beyond a face.
    grid->GetBounds(bounds);
    CHECK(bounds[0] >= -1e-12);
    CHECK(bounds[1] <= side + 1e-12);
    CHECK(bounds[2] >= -1e-12);
    CHECK(bounds[3] <= side + 1e-12);
    vtkIdType triangles = 0;
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) triangles += grid->GetCellType(c) == VTK_TRIANGLE;
    CHECK(triangles >= 2 * (grid->GetNumberOfPoints() - 2 * std::sqrt(double(grid->GetNumberOfPoints())) - 1));
    // An isotherm halfway between the coldest and the warmest point.
    vtkNew<vtkContourFilter> contour;
    contour->SetInputData(grid);
    contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "temperature");
    contour->SetValue(0, 0.5 * (range[0] + range[1]));
    contour->Update();
    CHECK(contour->GetOutput()->GetNumberOfLines() > 0);
  }
  CHECK(fs::exists(out / "open_in_paraview.py"));
  CHECK(test::read_text(out / "open_in_paraview.py").find("SOLID = True") != std::string::npos);
}
