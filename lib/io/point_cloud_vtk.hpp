// VTK output of a particle cloud: one .vtu per snapshot (named point fields
// on the particles; triangles between them where the caller gives them,
// else vertex cells) and a .pvd time collection for ParaView. Every file is
// written to a temporary name and renamed when complete.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "io/labels.hpp"

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
  // Triangles over the points (indices, counterclockwise), written as
  // VTK_TRIANGLE cells so that ParaView's Contour, Surface and Plot Over
  // Line work as on a finite-element mesh; every point in no triangle gets
  // a vertex cell. Empty: one vertex cell per point (grains, clouds).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // (name, text) pairs stored as the file's field data: the project, the
  // time unit, the frostwall version.
  Labels labels;
};

// The frame restricted to the points `keep` (indices, in that order), with
// every field and vector; triangles are not carried over.
PointCloudFrame subset(const PointCloudFrame& frame, const std::vector<std::size_t>& keep);

// Writes an XML UnstructuredGrid (.vtu), binary appended, to `file`.
void write_vtu(const std::filesystem::path& file, const PointCloudFrame& frame);

// A ParaView time collection: (time, file name relative to the .pvd).
struct PvdEntry {
  double time;
  std::string file;
};
void write_pvd(const std::filesystem::path& file, const std::vector<PvdEntry>& entries);

}  // namespace frostwall::io
