#include "io/grid_vtk.hpp"

#include <stdexcept>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkXMLImageDataWriter.h>

#include "io/atomic_file.hpp"
#include "io/labels.hpp"

namespace frostwall::io {

void write_vti(const std::filesystem::path& file, const GridFrame& frame) {
  vtkNew<vtkImageData> grid;
  // VTK counts points: one more than cells along each axis.
  grid->SetDimensions(frame.cells[0] + 1, frame.cells[1] + 1, frame.cells[2] + 1);
  grid->SetOrigin(frame.origin.data());
  grid->SetSpacing(frame.spacing.data());
  const std::size_t n = static_cast<std::size_t>(frame.cells[0]) * frame.cells[1] * frame.cells[2];
  auto add = [&](const std::string& name, const std::vector<double>& values, int components) {
    if (values.size() != n * components) throw std::invalid_argument("grid field '" + name + "' has the wrong size");
    vtkNew<vtkDoubleArray> array;
    array->SetName(name.c_str());
    array->SetNumberOfComponents(components);
    array->SetNumberOfTuples(static_cast<vtkIdType>(n));
    for (std::size_t i = 0; i < values.size(); ++i) array->SetValue(static_cast<vtkIdType>(i), values[i]);
    grid->GetCellData()->AddArray(array);
  };
  for (const auto& [name, values] : frame.fields) add(name, values, 1);
  for (const auto& [name, values] : frame.vectors) add(name, values, 3);
  add_labels(*grid->GetFieldData(), frame.labels);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLImageDataWriter> writer;
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    if (writer->Write() != 1) throw std::runtime_error("cannot write " + file.string());
  });
}

}  // namespace frostwall::io
