// Story: a whole run writes what the contract says. A small cooled strip is
// run through run_project; its VTK snapshot is read back with VTK's own XML
// reader (the particles of summary.json and the face row, which holds the
// face temperature: none of the layers beyond the face, which hold its
// antisymmetric extension; liquid fraction within [0, 1]; triangles between
// the particles),
// the .pvd lists every snapshot, and the heat balance closes.
#include <catch2/catch.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
namespace fs = std::filesystem;

TEST_CASE("A run writes VTK snapshots that VTK reads back, and summary.json", "[freezing][run][io]") {
  test::TempDir dir("frostwall-run");
  auto p = test::rectangle_project(
      0.495, 0.05,
      R"({ "left": { "temperature": -10 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
      R"("sand")", 5.0, 2 * 86400.0, test::numerics(0.01));
  p.time.snapshots = {86400.0, 2 * 86400.0};
  p.output.directory = (dir.path / "out").string();
  run::run_project(p, {});

  const fs::path out = dir.path / "out";
  std::ifstream in(out / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  CHECK(summary["project"] == "test");
  const std::size_t particles = summary["run"]["particles"], fixed = summary["run"]["boundary_particles"];
  // Face row at x = 0 fixed, mirror at 0.495 halfway between rows: 49 free columns x 5 rows.
  CHECK(particles == 49 * 5);
  REQUIRE(summary["front"].size() >= 2);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((out / "field_172800.vtu").c_str());  // named by the time in the project unit (s)
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  // The face row: one fixed particle per row of free ones (5); the layers
  // beyond the face (the rest of the fixed particles) are not written.
  REQUIRE(fixed > 5);
  REQUIRE(static_cast<std::size_t>(grid->GetNumberOfPoints()) == particles + 5);
  // 50 columns (49 free, the face row) x 5 rows of a lattice: 2 x 49 x 4 triangles.
  CHECK(grid->GetNumberOfCells() == 2 * 49 * 4);
  for (const char* name : {"temperature", "enthalpy", "liquid_fraction", "phase", "conductivity", "volume", "boundary"})
    CHECK(grid->GetPointData()->GetArray(name) != nullptr);
  vtkDataArray* T = grid->GetPointData()->GetArray("temperature");
  vtkDataArray* boundary = grid->GetPointData()->GetArray("boundary");
  vtkDataArray* f = grid->GetPointData()->GetArray("liquid_fraction");
  vtkDataArray* volume = grid->GetPointData()->GetArray("volume");
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    // The face row holds -10 C, and nothing is colder.
    if (boundary->GetTuple1(i) >= 0) {
      CHECK(std::abs(grid->GetPoint(i)[0]) < 1e-12);
      CHECK(T->GetTuple1(i) == -10.0);
    }
    CHECK(T->GetTuple1(i) >= -10.0);
    CHECK(f->GetTuple1(i) >= 0.0);
    CHECK(f->GetTuple1(i) <= 1.0);
    CHECK(volume->GetTuple1(i) == Approx(1e-4));
  }
  // Something froze next to the face after two days at -10 C.
  double coldest_free = 1e9;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
    if (boundary->GetTuple1(i) < 0) coldest_free = std::min(coldest_free, T->GetTuple1(i));
  CHECK(coldest_free < 0.0);

  std::ifstream pvd(out / "field.pvd");
  const std::string text((std::istreambuf_iterator<char>(pvd)), {});
  CHECK(text.find("field_86400.vtu") != std::string::npos);
  CHECK(text.find("field_172800.vtu") != std::string::npos);
  for (const auto& entry : fs::directory_iterator(out)) CHECK(entry.path().string().find(".tmp-") == std::string::npos);

  const double stored = summary["heat_balance"]["stored_change"],
               from_face = summary["heat_balance"]["from_boundaries"]["left"];
  CHECK(std::abs(stored - from_face) < 1e-9 * std::abs(stored));
}
