#include "report/png_image.hpp"

#include <cstring>
#include <stdexcept>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkUnsignedCharArray.h>

#include "report/base64.hpp"

namespace frostwall::report {

std::string encode_png(const RgbaImage& image) {
  if (image.width <= 0 || image.height <= 0) throw std::invalid_argument("png: empty image");
  vtkNew<vtkImageData> data;
  data->SetDimensions(image.width, image.height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  // VTK images start at the bottom row; ours at the top.
  auto* out = static_cast<std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = std::size_t(image.width) * 4;
  for (int y = 0; y < image.height; ++y)
    std::memcpy(out + std::size_t(image.height - 1 - y) * row, image.pixels.data() + std::size_t(y) * row, row);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->WriteToMemoryOn();
  writer->Write();
  vtkUnsignedCharArray* bytes = writer->GetResult();
  if (!bytes || bytes->GetNumberOfValues() == 0) throw std::runtime_error("png: the writer produced nothing");
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                     static_cast<std::size_t>(bytes->GetNumberOfValues()));
}

std::string png_data_uri(const RgbaImage& image) { return "data:image/png;base64," + base64(encode_png(image)); }

}  // namespace frostwall::report
