#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkVariant.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <unistd.h>

#include "io/atomic_file.hpp"
#include "temp_dir.hpp"
#include "io/point_cloud_vtk.hpp"

namespace fs = std::filesystem;
using namespace frostwall::io;

namespace {

using TempDir = frostwall::test::TempDir;

bool has_temporaries(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().filename().string().find(".tmp-") != std::string::npos) return true;
  return false;
}

PointCloudFrame make_frame(std::size_t n) {
  PointCloudFrame frame;
  std::vector<double> temperature(n), volume(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = static_cast<double>(i);
    frame.points.push_back({0.01 * x, -0.5 + 1e-3 * x, 1.0 / (1.0 + x)});
    temperature[i] = 273.15 - 0.1 * x;
    volume[i] = 1e-6 * (1.0 + x);
  }
  frame.fields.emplace_back("temperature", std::move(temperature));
  frame.fields.emplace_back("volume", std::move(volume));
  return frame;
}

}  // namespace

TEST_CASE("write_vtu round-trips points, vertex cells and fields", "[shared][io]") {
  TempDir dir;
  const std::size_t n = 1000;
  const auto frame = make_frame(n);
  const fs::path file = dir.path / "frame_0001.vtu";

  write_vtu(file, frame);
  REQUIRE(fs::exists(file));
  CHECK_FALSE(has_temporaries(dir.path));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  REQUIRE(grid != nullptr);
  REQUIRE(grid->GetNumberOfPoints() == static_cast<vtkIdType>(n));
  REQUIRE(grid->GetNumberOfCells() == static_cast<vtkIdType>(n));
  CHECK(grid->GetCellType(0) == VTK_VERTEX);
  CHECK(grid->GetCellType(n - 1) == VTK_VERTEX);

  // Binary appended output is exact, so compare bit for bit.
  double p[3];
  grid->GetPoint(437, p);
  CHECK(p[0] == frame.points[437][0]);
  CHECK(p[1] == frame.points[437][1]);
  CHECK(p[2] == frame.points[437][2]);

  vtkDataArray* temperature = grid->GetPointData()->GetArray("temperature");
  vtkDataArray* volume = grid->GetPointData()->GetArray("volume");
  REQUIRE(temperature != nullptr);
  REQUIRE(volume != nullptr);
  CHECK(temperature->GetNumberOfTuples() == static_cast<vtkIdType>(n));
  CHECK(temperature->GetDataType() == VTK_DOUBLE);
  CHECK(temperature->GetTuple1(612) == frame.fields[0].second[612]);
  CHECK(volume->GetTuple1(999) == frame.fields[1].second[999]);
}

TEST_CASE("write_vtu writes triangles, a vertex for a point in none, the labels, and a subset keeps its fields",
          "[shared][io]") {
  TempDir dir("frostwall-vtk");
  // A unit square split along a diagonal, and a fifth point in no triangle.
  PointCloudFrame frame;
  frame.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 0}};
  frame.fields = {{"temperature", {0, 1, 2, 1, 9}}};
  frame.vectors = {{"displacement", {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 0}}};
  frame.triangles = {{0, 1, 2}, {0, 2, 3}};
  frame.labels = {{"project", "square"}, {"time_unit", "h"}};
  const fs::path file = dir.path / "square.vtu";
  write_vtu(file, frame);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  REQUIRE(grid->GetNumberOfCells() == 3);
  CHECK(grid->GetCellType(0) == VTK_TRIANGLE);
  CHECK(grid->GetCellType(1) == VTK_TRIANGLE);
  CHECK(grid->GetCellType(2) == VTK_VERTEX);
  CHECK(grid->GetCell(2)->GetPointId(0) == 4);
  CHECK(grid->GetCell(1)->GetPointId(2) == 3);
  auto* project = grid->GetFieldData()->GetAbstractArray("project");
  REQUIRE(project != nullptr);
  CHECK(project->GetVariantValue(0).ToString() == "square");
  CHECK(grid->GetFieldData()->GetAbstractArray("time_unit")->GetVariantValue(0).ToString() == "h");

  const auto part = subset(frame, {4, 0});
  REQUIRE(part.points.size() == 2);
  CHECK(part.points[0][0] == 5.0);
  CHECK(part.fields[0].second == std::vector<double>{9, 0});
  CHECK(part.vectors[0].second == std::vector<double>{5, 5, 0, 0, 0, 0});
  CHECK(part.triangles.empty());
  CHECK(part.labels == frame.labels);

  frame.triangles.push_back({0, 1, 7});  // a corner beyond the points
  CHECK_THROWS_AS(write_vtu(dir.path / "bad.vtu", frame), std::invalid_argument);
  CHECK(!fs::exists(dir.path / "bad.vtu"));
}

TEST_CASE("write_vtu overwrites an existing file", "[shared][io]") {
  TempDir dir;
  const fs::path file = dir.path / "frame.vtu";
  write_vtu(file, make_frame(10));
  write_vtu(file, make_frame(20));

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  CHECK(reader->GetOutput()->GetNumberOfPoints() == 20);
  CHECK_FALSE(has_temporaries(dir.path));
}

TEST_CASE("write_vtu rejects a field whose size differs from the point count", "[shared][io]") {
  TempDir dir;
  auto frame = make_frame(100);
  frame.fields[1].second.pop_back();
  const fs::path file = dir.path / "bad.vtu";
  CHECK_THROWS_AS(write_vtu(file, frame), std::invalid_argument);
  CHECK_FALSE(fs::exists(file));
  CHECK_FALSE(has_temporaries(dir.path));
}

TEST_CASE("write_pvd lists every dataset with its time and file", "[shared][io]") {
  TempDir dir;
  const std::vector<PvdEntry> entries = {{0.0, "frame_0000.vtu"}, {0.1, "frame_0001.vtu"}, {86400.5, "frame_0002.vtu"}};
  const fs::path file = dir.path / "series.pvd";
  write_pvd(file, entries);
  REQUIRE(fs::exists(file));
  CHECK_FALSE(has_temporaries(dir.path));

  // A real XML parser, so malformed output fails here rather than in ParaView.
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.string().c_str());
  REQUIRE(parser->Parse() == 1);
  vtkXMLDataElement* root = parser->GetRootElement();
  REQUIRE(root != nullptr);
  CHECK(std::string(root->GetName()) == "VTKFile");
  CHECK(std::string(root->GetAttribute("type")) == "Collection");
  vtkXMLDataElement* collection = root->FindNestedElementWithName("Collection");
  REQUIRE(collection != nullptr);
  REQUIRE(collection->GetNumberOfNestedElements() == 3);
  for (int i = 0; i < 3; ++i) {
    vtkXMLDataElement* ds = collection->GetNestedElement(i);
    CHECK(std::string(ds->GetName()) == "DataSet");
    CHECK(std::string(ds->GetAttribute("file")) == entries[i].file);
    // Printed with 17 significant digits, so the time parses back exactly.
    CHECK(std::stod(ds->GetAttribute("timestep")) == entries[i].time);
  }
}

TEST_CASE("write_atomically leaves nothing behind when the writer throws", "[shared][io]") {
  TempDir dir;
  const fs::path file = dir.path / "out.txt";
  fs::path seen_tmp;
  CHECK_THROWS_AS(write_atomically(file,
                                   [&](const fs::path& tmp) {
                                     seen_tmp = tmp;
                                     std::ofstream(tmp) << "half written";  // a partial file
                                     throw std::runtime_error("writer failed");
                                   }),
                  std::runtime_error);
  CHECK(seen_tmp.parent_path() == dir.path);
  CHECK(seen_tmp.filename().string().rfind("out.txt.tmp-", 0) == 0);
  CHECK_FALSE(fs::exists(file));
  CHECK_FALSE(fs::exists(seen_tmp));
  CHECK_FALSE(has_temporaries(dir.path));
}

TEST_CASE("a failed rewrite keeps the previous file intact", "[shared][io]") {
  TempDir dir;
  const fs::path file = dir.path / "out.txt";
  write_text_file(file, "old\n");
  CHECK_THROWS(write_atomically(file, [](const fs::path&) { throw std::runtime_error("no"); }));
  std::ifstream in(file, std::ios::binary);
  std::string content((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(content == "old\n");
  CHECK_FALSE(has_temporaries(dir.path));
}

TEST_CASE("write_text_file reports a path it cannot write", "[shared][io]") {
  TempDir dir;
  const fs::path file = dir.path / "missing-dir" / "out.txt";
  try {
    write_text_file(file, "x");
    FAIL("expected std::runtime_error");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("missing-dir") != std::string::npos);
  }
}

TEST_CASE("write_vtu throws when VTK cannot write the file", "[shared][io]") {
  TempDir dir;
  const fs::path file = dir.path / "missing-dir" / "frame.vtu";
  // VTK reports the failure on stderr as well; silence it for this check.
  const bool warnings = vtkObject::GetGlobalWarningDisplay();
  vtkObject::GlobalWarningDisplayOff();
  CHECK_THROWS_AS(write_vtu(file, make_frame(10)), std::runtime_error);
  vtkObject::SetGlobalWarningDisplay(warnings);
  CHECK_FALSE(fs::exists(file));
}
