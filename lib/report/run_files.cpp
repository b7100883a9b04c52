#include "report/run_files.hpp"

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

namespace frostwall::report {

namespace fs = std::filesystem;

namespace {

void require_file(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw std::runtime_error("missing output file " + file.string());
}

}  // namespace

namespace {
// The particles of a .vtu snapshot (throws when there are none).
vtkSmartPointer<vtkUnstructuredGrid> read_grid(const fs::path& file) {
  require_file(file);
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkSmartPointer<vtkUnstructuredGrid> grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfPoints() == 0) throw std::runtime_error("no particles in " + file.string());
  return grid;
}
}  // namespace

FieldSnapshot read_field(const fs::path& file) {
  const auto grid = read_grid(file);
  auto array = [&](const char* name) {
    vtkDataArray* a = grid->GetPointData()->GetArray(name);
    if (!a) throw std::runtime_error(file.string() + ": no point field '" + name + "'");
    return a;
  };
  vtkDataArray *T = array("temperature"), *V = array("volume"), *B = array("boundary");
  FieldSnapshot s;
  const vtkIdType n = grid->GetNumberOfPoints();
  s.position.reserve(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const double* x = grid->GetPoint(i);
    s.position.emplace_back(x[0], x[1]);
    s.temperature.push_back(T->GetTuple1(i));
    s.volume.push_back(V->GetTuple1(i));
    s.boundary.push_back(static_cast<int>(std::lround(B->GetTuple1(i))));
  }
  if (vtkDataArray* q = grid->GetPointData()->GetArray("darcy_flux"))
    for (vtkIdType i = 0; i < n; ++i) s.darcy_flux.emplace_back(q->GetTuple3(i)[0], q->GetTuple3(i)[1]);
  return s;
}

GrainSnapshot read_grains(const fs::path& file) {
  const auto grid = read_grid(file);
  GrainSnapshot s;
  vtkDataArray *D = grid->GetPointData()->GetArray("diameter"), *U = grid->GetPointData()->GetArray("displacement");
  if (!D || !U) return s;
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    const double* x = grid->GetPoint(i);
    s.position.push_back({x[0], x[1], x[2]});
    s.diameter.push_back(D->GetTuple1(i));
    const double* u = U->GetTuple3(i);
    s.displacement.push_back(std::hypot(u[0], u[1], u[2]));
  }
  return s;
}

SolidSnapshot read_solid(const fs::path& file) {
  const auto grid = read_grid(file);
  SolidSnapshot s;
  vtkDataArray *U = grid->GetPointData()->GetArray("displacement"), *D = grid->GetPointData()->GetArray("damage"),
               *V = grid->GetPointData()->GetArray("volume"), *B = grid->GetPointData()->GetArray("boundary");
  if (!U || !D || !V || !B) return s;
  vtkDataArray *T = grid->GetPointData()->GetArray("temperature"), *M = grid->GetPointData()->GetArray("material");
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    if (std::lround(B->GetTuple1(i)) >= 0) continue;  // thermal layers: not solid
    const double* x = grid->GetPoint(i);
    const double* u = U->GetTuple3(i);
    s.particles.position.emplace_back(x[0], x[1]);
    s.particles.volume.push_back(V->GetTuple1(i));
    s.particles.boundary.push_back(-1);
    s.particles.temperature.push_back(std::hypot(u[0], u[1]));
    s.damage.push_back(D->GetTuple1(i));
    if (T) s.temperature.push_back(T->GetTuple1(i));
    if (M) s.material.push_back(static_cast<int>(std::lround(M->GetTuple1(i))));
  }
  return s;
}

std::vector<post::Polyline> read_polylines(const fs::path& file) {
  require_file(file);
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  std::vector<post::Polyline> lines;
  if (!data || !data->GetLines()) return lines;
  vtkCellArray* cells = data->GetLines();
  vtkNew<vtkIdList> ids;
  cells->InitTraversal();
  while (cells->GetNextCell(ids)) {
    post::Polyline line;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const double* x = data->GetPoint(ids->GetId(k));
      line.points.emplace_back(x[0], x[1]);
    }
    line.closed = ids->GetNumberOfIds() > 2 && ids->GetId(0) == ids->GetId(ids->GetNumberOfIds() - 1);
    if (line.closed) line.points.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

std::vector<PvdEntry> read_pvd(const fs::path& file) {
  std::vector<PvdEntry> out;
  const auto text = read_text(file);
  if (!text) return out;
  static const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)")re");
  for (auto it = std::sregex_iterator(text->begin(), text->end(), dataset); it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1].str()), (*it)[2].str()});
  return out;
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON");
  }
}

std::optional<std::string> read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace frostwall::report
