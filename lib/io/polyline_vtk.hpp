// VTK output of isolines (the frozen front, interface_XXXX.vtp): one
// polyline cell per curve, written atomically like every other output file.
#pragma once

#include <filesystem>
#include <vector>

#include "geometry/polyline.hpp"
#include "io/labels.hpp"

namespace frostwall::io {

// Writes an XML PolyData (.vtp), binary appended: the points of every line
// (z = 0) and one VTK_POLY_LINE per line; a closed line repeats its first
// point id at the end so ParaView draws it closed. No lines: a valid empty file.
// labels: the file's field data (io/labels.hpp).
void write_vtp(const std::filesystem::path& file, const std::vector<geometry::Polyline>& lines,
               const Labels& labels = {});

}  // namespace frostwall::io
