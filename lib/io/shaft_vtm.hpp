// shaft.vtm: the shaft as built in 3-D for ParaView, a multiblock of
//  - "sections": each section's last snapshot (its particles and their
//    triangles, as the section's own files) moved down to z = -depth;
//  - "pipes": every freeze pipe's as-built trace as a polyline from its
//    collar (z = 0) to its bottom, with cell data `pipe` (its number) and
//    `failed` (1 for a pipe that is off).
// The blocks' files go to shaft/ beside it; all are written atomically.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace frostwall::io {

struct ShaftVtmSection {
  double depth = 0.0;            // m, down
  std::filesystem::path source;  // a section's .vtu
  std::string name;              // the block's name
};

struct ShaftVtmPipe {
  int number = 0;
  bool failed = false;
  std::vector<std::array<double, 3>> points;  // x, y, vertical depth (down)
};

void write_shaft_vtm(const std::filesystem::path& directory, const std::vector<ShaftVtmSection>& sections,
                     const std::vector<ShaftVtmPipe>& pipes);

}  // namespace frostwall::io
