#include "io/shaft_vtm.hpp"

#include <fmt/core.h>
#include <stdexcept>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "io/atomic_file.hpp"
#include "io/xml_escape.hpp"

namespace frostwall::io {

namespace fs = std::filesystem;

namespace {

void write_section(const fs::path& file, const ShaftVtmSection& s) {
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName(s.source.string().c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  if (!grid || grid->GetNumberOfPoints() == 0)
    throw std::runtime_error("shaft.vtm: no particles in " + s.source.string());
  vtkPoints* points = grid->GetPoints();
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i) {
    double x[3];
    points->GetPoint(i, x);
    points->SetPoint(i, x[0], x[1], -s.depth);
  }
  write_atomically(file, [&](const fs::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();
    writer->SetHeaderTypeToUInt64();
    writer->SetCompressorTypeToLZ4();
    if (writer->Write() != 1) throw std::runtime_error("shaft.vtm: VTK failed to write " + tmp.string());
  });
}

void write_pipes(const fs::path& file, const std::vector<ShaftVtmPipe>& pipes) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> number, failed;
  number->SetName("pipe");
  failed->SetName("failed");
  for (const auto& p : pipes) {
    lines->InsertNextCell(static_cast<int>(p.points.size()));
    for (const auto& x : p.points) lines->InsertCellPoint(points->InsertNextPoint(x[0], x[1], -x[2]));
    number->InsertNextValue(p.number);
    failed->InsertNextValue(p.failed ? 1 : 0);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetCellData()->AddArray(number);
  data->GetCellData()->AddArray(failed);
  write_atomically(file, [&](const fs::path& tmp) {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(tmp.string().c_str());
    writer->SetInputData(data);
    if (writer->Write() != 1) throw std::runtime_error("shaft.vtm: VTK failed to write " + tmp.string());
  });
}

}  // namespace

void write_shaft_vtm(const fs::path& directory, const std::vector<ShaftVtmSection>& sections,
                     const std::vector<ShaftVtmPipe>& pipes) {
  fs::create_directories(directory / "shaft");
  std::string blocks = "    <Block index=\"0\" name=\"sections\">\n";
  for (std::size_t k = 0; k < sections.size(); ++k) {
    const std::string name = fmt::format("shaft/section_{:06.2f}m.vtu", sections[k].depth);
    write_section(directory / name, sections[k]);
    blocks +=
        fmt::format("      <DataSet index=\"{}\" name=\"{}\" file=\"{}\"/>\n", k, xml_escape(sections[k].name), name);
  }
  blocks += "    </Block>\n    <Block index=\"1\" name=\"pipes\">\n";
  write_pipes(directory / "shaft/pipes.vtp", pipes);
  blocks += "      <DataSet index=\"0\" name=\"pipe traces\" file=\"shaft/pipes.vtp\"/>\n    </Block>\n";
  write_text_file(directory / "shaft.vtm",
                  "<?xml version=\"1.0\"?>\n<VTKFile type=\"vtkMultiBlockDataSet\" version=\"1.0\">\n"
                  "  <vtkMultiBlockDataSet>\n" +
                      blocks + "  </vtkMultiBlockDataSet>\n</VTKFile>\n");
}

}  // namespace frostwall::io
