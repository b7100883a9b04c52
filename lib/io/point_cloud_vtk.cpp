#include "io/point_cloud_vtk.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "io/atomic_file.hpp"
#include "io/labels.hpp"
#include "io/xml_escape.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

namespace {

// Triangles where given, and a vertex cell for each point in none of them
// (all points when there are no triangles), built as flat offset and
// connectivity arrays in one pass instead of per-cell inserts.
void set_cells(vtkUnstructuredGrid& grid, const PointCloudFrame& frame) {
  const auto n = static_cast<vtkIdType>(frame.points.size());
  std::vector<char> used(n, 0);
  for (const auto& t : frame.triangles)
    for (auto v : t) {
      if (v >= frame.points.size())
        throw std::invalid_argument(fmt::format("write_vtu: triangle corner {} of {} points", v, n));
      used[v] = 1;
    }
  vtkIdType lonely = 0;
  for (char u : used) lonely += !u;
  const auto triangles = static_cast<vtkIdType>(frame.triangles.size());
  const vtkIdType cells = triangles + lonely;
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  vtkNew<vtkUnsignedCharArray> types;
  offsets->SetNumberOfValues(cells + 1);
  connectivity->SetNumberOfValues(3 * triangles + lonely);
  types->SetNumberOfValues(cells);
  vtkIdType c = 0, at = 0;
  for (const auto& t : frame.triangles) {
    offsets->SetValue(c, at);
    types->SetValue(c++, VTK_TRIANGLE);
    for (auto v : t) connectivity->SetValue(at++, v);
  }
  for (vtkIdType i = 0; i < n; ++i)
    if (!used[i]) {
      offsets->SetValue(c, at);
      types->SetValue(c++, VTK_VERTEX);
      connectivity->SetValue(at++, i);
    }
  offsets->SetValue(cells, at);
  vtkNew<vtkCellArray> array;
  array->SetData(offsets, connectivity);
  grid.SetCells(types, array);
}

}  // namespace

PointCloudFrame subset(const PointCloudFrame& frame, const std::vector<std::size_t>& keep) {
  PointCloudFrame out;
  out.single_precision = frame.single_precision;
  out.labels = frame.labels;
  out.points.reserve(keep.size());
  for (std::size_t i : keep) out.points.push_back(frame.points.at(i));
  auto pick = [&](const auto& source, std::size_t components, auto& target) {
    for (const auto& [name, values] : source) {
      std::vector<double> kept;
      kept.reserve(components * keep.size());
      for (std::size_t i : keep)
        for (std::size_t c = 0; c < components; ++c) kept.push_back(values.at(components * i + c));
      target.emplace_back(name, std::move(kept));
    }
  };
  pick(frame.fields, 1, out.fields);
  pick(frame.vectors, 3, out.vectors);
  return out;
}

void write_vtu(const fs::path& file, const PointCloudFrame& frame) {
  const auto n = static_cast<vtkIdType>(frame.points.size());
  // Validate before touching the file system so a bad frame leaves nothing.
  for (const auto& [name, values] : frame.fields) {
    if (values.size() != frame.points.size())
      throw std::invalid_argument(
          fmt::format("write_vtu: field '{}' has {} values for {} points", name, values.size(), n));
  }
  for (const auto& [name, values] : frame.vectors)
    if (values.size() != 3 * frame.points.size())
      throw std::invalid_argument(
          fmt::format("write_vtu: vector '{}' has {} values for {} points", name, values.size(), n));

  vtkNew<vtkPoints> points;
  if (frame.single_precision) points->SetDataTypeToFloat();
  else points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i) points->SetPoint(i, frame.points[i].data());

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  set_cells(*grid, frame);
  add_labels(*grid->GetFieldData(), frame.labels);

  auto add = [&](const std::string& name, const std::vector<double>& values, int components) {
    vtkSmartPointer<vtkDataArray> array;
    if (frame.single_precision) array = vtkSmartPointer<vtkFloatArray>::New();
    else array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(name.c_str());
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
      for (int c = 0; c < components; ++c) array->SetComponent(i, c, values[i * components + c]);
    grid->GetPointData()->AddArray(array);
  };
  for (const auto& [name, values] : frame.fields) add(name, values, 1);
  for (const auto& [name, values] : frame.vectors) add(name, values, 3);

  write_atomically(file, [&](const fs::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary, not base64
    writer->SetHeaderTypeToUInt64();  // the UInt32 default overflows past 4 GiB per array
    // Cell connectivity as Int32 (half the bytes) while the indices fit.
    if (n < vtkIdType(1) << 31) writer->SetIdTypeToInt32();
    // LZ4: about as small as zlib on the fields, several times faster to
    // write. zlib (level 1) halves the triangles' connectivity, but made the
    // main job 1.48x slower to run (bench/README.md).
    writer->SetCompressorTypeToLZ4();
    // Write() reports failure only through its return value (1 = success).
    if (writer->Write() != 1) throw std::runtime_error("write_vtu: VTK failed to write " + tmp.string());
  });
}

void write_pvd(const fs::path& file, const std::vector<PvdEntry>& entries) {
  std::string xml = "<?xml version=\"1.0\"?>\n"
                    "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
                    "  <Collection>\n";
  for (const auto& e : entries) {
    // {:.17g} round-trips every double, so ParaView sees the exact times;
    // file names are arbitrary strings, escaped so the XML stays well formed.
    xml += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
                       xml_escape(e.file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_text_file(file, xml);
}

}  // namespace frostwall::io
