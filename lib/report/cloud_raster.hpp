// A particle field drawn as ParaView draws the VTK cells: piecewise linear
// over the particles' own triangles (geometry::cloud_triangles, Delaunay
// without the slivers across holes and concave sides). Each pixel centre
// inside a triangle takes the barycentric mix of its three corners'
// values; pixels in no triangle stay transparent. The triangles and each
// pixel's weights are found once and reused for every snapshot and field
// (particles do not move).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "particles/vec.hpp"
#include "report/colour_scale.hpp"
#include "report/field_map.hpp"
#include "report/png_image.hpp"

namespace frostwall::report {

class CloudRaster {
 public:
  // `max_edge` (m): longer triangle edges are holes, not ground.
  CloudRaster(const std::vector<particles::Vec<2>>& points, double max_edge, const MapWindow& window);

  // The field at the pixel centres (NaN outside the triangles), rows top
  // to bottom; `values[i]` belongs to points[i] of the constructor.
  std::vector<double> sample(const std::vector<double>& values) const;
  RgbaImage raster(const std::vector<double>& values, const ColourScale& colours) const;

  std::size_t triangles() const { return triangles_; }
  std::size_t covered_pixels() const { return pixels_.size(); }

 private:
  struct Pixel {
    std::size_t index;  // in the raster
    std::array<std::uint32_t, 3> corner;
    std::array<double, 3> weight;
  };
  std::vector<Pixel> pixels_;
  std::size_t points_ = 0, triangles_ = 0;
  MapWindow window_;
};

// A square window over the points' extent, half a spacing beyond it.
MapWindow window_over(const std::vector<particles::Vec<2>>& points, double spacing, int pixels);

}  // namespace frostwall::report
