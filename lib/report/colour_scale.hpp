// The temperature colours of the maps: a diverging scale (cool-warm) that
// turns from blue to red at the freezing point, so frozen ground reads as
// blue whatever the range; and its colour bar as SVG, with degC ticks.
#pragma once

#include <array>
#include <cstdint>
#include <string>

namespace frostwall::report {

class ColourScale {
 public:
  // The scale spans [lo, hi]; `pivot` (the freezing point) gets the neutral
  // middle colour when it lies inside, else the scale is plain linear.
  ColourScale(double lo, double hi, double pivot);

  std::array<std::uint8_t, 3> operator()(double T) const;
  double lo() const { return lo_; }
  double hi() const { return hi_; }

  // A horizontal bar `width` px wide with ticks and the title (default
  // "temperature (°C)"); the pivot is marked (as the freezing point when
  // the quantity is the temperature).
  std::string colour_bar_svg(int width, const std::string& quantity = "temperature (°C)") const;

 private:
  double position(double T) const;  // [0, 1] along the colour table
  double value_at(double s) const;  // inverse of position
  double lo_, hi_, pivot_;
  bool diverging_;
};

}  // namespace frostwall::report
