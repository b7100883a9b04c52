#include "io/point_cloud_vtk.hpp"

#include <stdexcept>

#include <fmt/format.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "io/atomic_file.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

void write_vtu(const fs::path& file, const PointCloudFrame& frame) {
  const auto n = static_cast<vtkIdType>(frame.points.size());
  // Validate before touching the file system so a bad frame leaves nothing.
  for (const auto& [name, values] : frame.fields) {
    if (values.size() != frame.points.size())
      throw std::invalid_argument(fmt::format(
          "write_vtu: field '{}' has {} values for {} points", name, values.size(), n));
  }
  for (const auto& [name, values] : frame.vectors)
    if (values.size() != 3 * frame.points.size())
      throw std::invalid_argument(fmt::format("write_vtu: vector '{}' has {} values for {} points", name, values.size(), n));

  vtkNew<vtkPoints> points;
  if (frame.single_precision) points->SetDataTypeToFloat();
  else points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType i = 0; i < n; ++i) points->SetPoint(i, frame.points[i].data());

  // One VTK_VERTEX per point, built as flat offsets/connectivity arrays in a
  // single pass instead of n InsertNextCell calls.
  vtkNew<vtkIdTypeArray> offsets;
  vtkNew<vtkIdTypeArray> connectivity;
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i) {
    offsets->SetValue(i, i);
    connectivity->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(VTK_VERTEX, cells);

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
    // LZ4: about as small as zlib on these fields, several times faster to write.
    writer->SetCompressorTypeToLZ4();
    // Write() reports failure only through its return value (1 = success).
    if (writer->Write() != 1)
      throw std::runtime_error("write_vtu: VTK failed to write " + tmp.string());
  });
}

namespace {

// File names are arbitrary strings; escape them so the XML stays well formed.
std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace

void write_pvd(const fs::path& file, const std::vector<PvdEntry>& entries) {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& e : entries) {
    // {:.17g} round-trips every double, so ParaView sees the exact times.
    xml += fmt::format("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                       e.time, xml_escape(e.file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_text_file(file, xml);
}

}  // namespace frostwall::io
