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
  bool markers = false;  // a dot at every point (sparse data, single points)
  double width = 1.6;    // stroke width in px
};

// Error bars: y +- error at each x, with a dot at y and caps at the ends;
// the axis reaches the ends.
struct ErrorBars {
  std::vector<double> x, y, error;
  std::string colour = "#000000";
};

// A reference line across the plot: vertical at x = value, or horizontal at y = value.
struct Guide {
  bool vertical = false;
  double value = 0.0;
  std::string label;
};

struct Chart {
  std::string title;             // the figure's accessible name (<title>)
  std::string x_label, y_label;  // with units, e.g. "time (d)"
  std::vector<Series> series;
  std::vector<Guide> guides;
  std::vector<ErrorBars> error_bars;
  std::vector<double> x_include, y_include;  // values the axes must reach (e.g. 0)
  std::string empty_note = "no values";      // written across the plot when no series has a point
  int width = 540, height = 330;
};

std::string render_svg(const Chart& chart);

// One row of a horizontal bar chart over time (the pores' freezing): from
// start to end. A NaN end: not ended, the bar runs open (fading, no right
// edge) to the chart's open_end; a NaN start: never started, no bar but a
// note in the row.
struct Bar {
  std::string label;  // at the row's left
  double start = 0.0, end = 0.0;
};

struct BarChart {
  std::string title;          // the figure's accessible name (<title>)
  std::string x_label;        // with units
  std::vector<Bar> bars;      // top to bottom
  std::vector<Guide> guides;  // vertical ones only
  std::vector<double> x_include;
  double open_end = 0.0;  // where unended bars stop (the end of the run)
  std::string colour = "#0072B2";
  std::string never_started = "not started";
  int width = 540, row_height = 18;
};

// Every row is a <g class="bar">, "bar open" or "bar never">.
std::string render_svg(const BarChart& chart);

// Okabe-Ito colours, distinguishable with colour-blind vision.
const std::vector<std::string>& categorical_colours();
// n colours along a dark-to-light ramp (plasma), for a progression such as snapshot days.
std::vector<std::string> sequential_colours(std::size_t n);

}  // namespace frostwall::report
