// Line charts as inline SVG, drawn like a journal figure: L-shaped axes
// with outward ticks at round numbers, axis titles with units, a faint
// grid, a legend beside the plot, dashed reference lines (a required
// thickness, the closure day). Used for the report's and the study's plots.
#pragma once

#include <string>
#include <vector>

namespace frostwall::report {

struct Series {
  std::string label;         // legend entry; empty = not in the legend
  std::vector<double> x, y;  // a NaN in either breaks the line there
  std::string colour;        // CSS colour; empty = the next categorical colour
  bool dashed = false;
  bool markers = false;      // a dot at every point (sparse data, single points)
  double width = 1.6;        // stroke width in px
};

// A reference line across the plot: vertical at x = value, or horizontal at y = value.
struct Guide {
  bool vertical = false;
  double value = 0.0;
  std::string label;
};

struct Chart {
  std::string title;            // the figure's accessible name (<title>)
  std::string x_label, y_label; // with units, e.g. "time (d)"
  std::vector<Series> series;
  std::vector<Guide> guides;
  std::vector<double> x_include, y_include;  // values the axes must reach (e.g. 0)
  std::string empty_note = "no values";      // written across the plot when no series has a point
  int width = 540, height = 330;
};

std::string render_svg(const Chart& chart);

// Okabe-Ito colours, distinguishable with colour-blind vision.
const std::vector<std::string>& categorical_colours();
// n colours along a dark-to-light ramp (plasma), for a progression such as snapshot days.
std::vector<std::string> sequential_colours(std::size_t n);

}  // namespace frostwall::report
