#include "io/polyline_vtk.hpp"

#include <stdexcept>

#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include "io/atomic_file.hpp"
#include "io/labels.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

void write_vtp(const fs::path& file, const std::vector<geometry::Polyline>& lines, const Labels& labels) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> cells;
  for (const auto& line : lines) {
    if (line.points.empty()) continue;  // a cell without points means nothing
    const vtkIdType first = points->GetNumberOfPoints();
    const auto n = static_cast<vtkIdType>(line.points.size());
    cells->InsertNextCell(n + (line.closed ? 1 : 0));
    for (vtkIdType k = 0; k < n; ++k) {
      const auto& x = line.points[static_cast<std::size_t>(k)];
      cells->InsertCellPoint(points->InsertNextPoint(x[0], x[1], 0.0));
    }
    if (line.closed) cells->InsertCellPoint(first);
  }

  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(cells);

  write_atomically(file, [&](const fs::path& tmp) {
    add_labels(*data->GetFieldData(), labels);
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(data);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw binary, not base64
    writer->SetHeaderTypeToUInt64();  // as the .vtu files: no 4 GiB limit per array
    // Write() reports failure only through its return value (1 = success).
    if (writer->Write() != 1) throw std::runtime_error("write_vtp: VTK failed to write " + tmp.string());
  });
}

}  // namespace frostwall::io
