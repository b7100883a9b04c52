// Temperature maps (the paper's Fig. 4): the particle field of a snapshot
// resampled onto a square raster by the run's own Shepard interpolation
// (post::FieldSampler, mirror images included), every pixel folded into the
// simulated wedge first, so one wedge draws the whole ring. The weights are
// computed once (particles do not move) and reused for every snapshot. The
// raster (a PNG <img>) gets the pipes, the excavation, the frozen front and
// a scale bar drawn on top as vectors (an SVG laid over it).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "post/isoline.hpp"
#include "report/colour_scale.hpp"
#include "report/png_image.hpp"
#include "report/run_files.hpp"
#include "report/wedge_symmetry.hpp"

namespace frostwall::report {

// A square of the section plane: lower-left corner and side (m), and the
// raster's pixels per side.
struct MapWindow {
  double x0 = 0.0, y0 = 0.0, size = 1.0;
  int pixels = 400;
};

struct Circle {
  double x = 0.0, y = 0.0, r = 0.0;
};

// An arrow of the flow field from (x, y), (dx, dy) long (m on the map).
struct Arrow {
  double x = 0.0, y = 0.0, dx = 0.0, dy = 0.0;
};

// What is drawn on top of every map.
struct MapOverlay {
  std::vector<Circle> pipes;
  std::vector<Arrow> arrows;       // the groundwater's flow (white, thin)
  double excavation_radius = 0.0;  // 0 = none
  double lining_radius = 0.0;      // the lining's inner face; 0 = none
  double domain_radius = 0.0;      // pixels beyond are left blank; 0 = no limit
};

class FieldMap {
 public:
  // `particles` fixes positions, volumes and boundary flags for every
  // snapshot; `kernel` is summary.json's name ("wendland_c2", "cubic_spline").
  FieldMap(const FieldSnapshot& particles, const WedgeSymmetry& symmetry, const std::string& kernel, double h,
           double spacing, const MapWindow& window, double domain_radius);
  ~FieldMap();

  // Pixels outside the domain, or with no particle in reach, are transparent.
  RgbaImage raster(const std::vector<double>& temperature, const ColourScale& colours) const;

  // Categories that must not blend (the material of a porous plate): each
  // pixel takes the colour of its nearest particle (colours[i] is particle
  // i's, as in the snapshot given to the constructor); pixels with no
  // particle within `reach` spacings are transparent.
  RgbaImage nearest_raster(const std::vector<std::array<std::uint8_t, 3>>& colours, double reach = 1.0) const;

  // The map as HTML: the raster as an <img> (PNG data URI) under an SVG with
  // the overlay, the front curves (wedge curves copied around by the
  // symmetry unless `fronts_whole`: they cover the section already), a title
  // and a scale bar.
  std::string html(const std::vector<double>& temperature, const ColourScale& colours,
                   const std::vector<post::Polyline>& fronts, bool fronts_whole, const MapOverlay& overlay,
                   const std::string& title) const;
  // The same around a raster made elsewhere (window-sized, e.g.
  // nearest_raster's); `what` names the map in the image's alt text.
  std::string html(const RgbaImage& image, const std::string& what, const std::vector<post::Polyline>& fronts,
                   bool fronts_whole, const MapOverlay& overlay, const std::string& title) const;

  const MapWindow& window() const { return window_; }

 private:
  struct Probe;
  std::unique_ptr<Probe> probe_;
  WedgeSymmetry symmetry_;
  MapWindow window_;
  double spacing_ = 0.0;
};

// A square raster `pixels` wide of values (rows top to bottom), each
// finite one in its colour; NaN pixels transparent.
RgbaImage paint(const std::vector<double>& values, int pixels, const ColourScale& colours);

// The map as HTML around a window-sized raster: the raster as an <img>
// (PNG data URI) under an SVG with the overlay, the curves as given (a
// white halo under a black line), a title and a scale bar; `what` names
// the map in the image's alt text.
std::string map_html(const RgbaImage& image, const MapWindow& window, const std::string& what,
                     const std::vector<post::Polyline>& curves, const MapOverlay& overlay, const std::string& title);

// The wedge's front curves copied around (identity only when the field
// already covers the whole circle). An open curve ending within `snap` of a
// wedge side is extended onto it, so that it meets its mirror copy.
std::vector<post::Polyline> unfold(const std::vector<post::Polyline>& wedge_curves, const WedgeSymmetry& symmetry,
                                   double snap);

// True when the free particles lie in the wedge (a wedge run); false when
// they cover more (numerics.symmetry "off": the field is the full ring).
bool field_is_wedge(const FieldSnapshot& particles, const WedgeSymmetry& symmetry, double spacing);

}  // namespace frostwall::report
