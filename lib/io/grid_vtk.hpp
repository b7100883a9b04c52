// VTK output of a regular grid of cells (the CFD-DEM fluid): an XML
// ImageData file (.vti) with named cell fields, written to a temporary
// name and renamed when complete.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/labels.hpp"

namespace frostwall::io {

struct GridFrame {
  std::array<double, 3> origin{}, spacing{};  // m
  std::array<int, 3> cells{};
  // (name, one value per cell, x fastest), and vectors (three per cell)
  std::vector<std::pair<std::string, std::vector<double>>> fields, vectors;
  Labels labels;  // the file's field data (io/labels.hpp)
};

void write_vti(const std::filesystem::path& file, const GridFrame& frame);

}  // namespace frostwall::io
