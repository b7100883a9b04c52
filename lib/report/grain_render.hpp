// A 3-D picture of the grains coloured by a value (the report's view of a
// CFD-DEM snapshot): every grain drawn as a shaded sphere into a depth
// buffer, seen from a chosen direction in orthographic projection, and
// encoded with VTK's PNG writer. It is a software rasteriser on purpose:
// Debian's VTK 9.1 renders through GLX and needs an X display, which CI
// machines and batch nodes lack; spheres are the one primitive we need and
// a depth buffer draws 116 000 of them in a fraction of a second.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "report/png_image.hpp"

namespace frostwall::report {

struct GrainView {
  int up_axis = 2;              // the vertical (against gravity) on the picture
  double azimuth_deg = -60.0;   // camera direction around the vertical, from the first horizontal axis
  double elevation_deg = 25.0;  // camera height above the horizontal
  int width = 560, height = 460;
  // A cut-away: only grains whose centre has coordinate `cut_axis` at least
  // `cut_at` are drawn (-1: no cut).
  int cut_axis = -1;
  double cut_at = 0.0;
};

// The picture's extent is that of the box [low, high], whatever is drawn
// inside it, so pictures of one run at different times line up. Pixels
// with no grain are transparent.
RgbaImage render_grains(const std::vector<std::array<double, 3>>& centre, const std::vector<double>& diameter,
                        const std::vector<std::array<std::uint8_t, 3>>& colour, const std::array<double, 3>& low,
                        const std::array<double, 3>& high, const GrainView& view);

}  // namespace frostwall::report
