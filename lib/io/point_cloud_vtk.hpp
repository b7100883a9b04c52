// VTK output of a particle cloud: one .vtu per snapshot (points as vertex
// cells with named point fields) and a .pvd time collection for ParaView.
// Every file is written to a temporary name and renamed when complete.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace frostwall::io {

struct PointCloudFrame {
  std::vector<std::array<double, 3>> points;
  // (name, one value per point); every field has points.size() values
  std::vector<std::pair<std::string, std::vector<double>>> fields;
  // (name, three values per point: x, y, z), e.g. the displacement
  std::vector<std::pair<std::string, std::vector<double>>> vectors;
  // Float32 points and fields: for large views (the full ring) where the
  // file size and write time matter more than the last digits.
  bool single_precision = false;
};

// Writes an XML UnstructuredGrid (.vtu), binary appended, to `file`.
void write_vtu(const std::filesystem::path& file, const PointCloudFrame& frame);

// A ParaView time collection: (time, file name relative to the .pvd).
struct PvdEntry {
  double time;
  std::string file;
};
void write_pvd(const std::filesystem::path& file, const std::vector<PvdEntry>& entries);

}  // namespace frostwall::io
