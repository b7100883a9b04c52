#include "report/svg_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/core.h>
#include <limits>

#include "io/xml_escape.hpp"
#include "report/nice_scale.hpp"
#include "report/svg.hpp"

namespace frostwall::report {

namespace {

using io::xml_escape;
using svg::num;

constexpr double font = 12.0, small_font = 10.5, tick_length = 4.0, legend_swatch = 22.0, legend_row = 17.0;

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  bool empty() const { return !(lo <= hi); }
};

// The polyline's pieces between NaNs, as "x,y x,y ..." in pixels.
template <class ToPx>
std::vector<std::string> pieces(const Series& s, ToPx&& to_px) {
  std::vector<std::string> out;
  std::string current;
  const std::size_t n = std::min(s.x.size(), s.y.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
      if (!current.empty()) out.push_back(std::move(current)), current.clear();
      continue;
    }
    const auto [px, py] = to_px(s.x[i], s.y[i]);
    if (!current.empty()) current += ' ';
    current.append(num(px)).append(",").append(num(py));
  }
  if (!current.empty()) out.push_back(std::move(current));
  return out;
}

// The horizontal axis both chart kinds draw on a plot area (left, top,
// pw x ph): its grid lines, tick marks, tick labels, and the frame's
// corner (left side and bottom).
struct XAxis {
  const NiceScale& scale;
  double left, top, pw, ph;
  double px(double x) const { return left + (x - scale.lo) / (scale.hi - scale.lo) * pw; }
  std::string grid() const {
    std::string o;
    for (double v : scale.ticks)
      o += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)", num(px(v)), num(top), num(top + ph));
    return o;
  }
  std::string ticks() const {
    std::string o;
    for (double v : scale.ticks)
      o += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)", num(px(v)), num(top + ph),
                       num(top + ph + tick_length));
    return o;
  }
  std::string frame() const {
    return fmt::format(R"(<polyline fill="none" points="{0},{1} {0},{2} {3},{2}"/>)", num(left), num(top),
                       num(top + ph), num(left + pw));
  }
  std::string labels() const {
    std::string o;
    for (double v : scale.ticks)
      o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)", num(px(v)),
                       num(top + ph + tick_length + 13), tick_label(v, scale.decimals));
    return o;
  }
};

// The plot area, px.
struct PlotArea {
  double left, top, pw, ph;
};

// Reference lines under the data, their labels with a white halo, readable
// where a curve passes under them.
template <class Px, class Py>
std::string guides_svg(const Chart& chart, const Px& px, const Py& py, const PlotArea& area, const std::string& clip) {
  const auto [left, top, pw, ph] = area;
  std::string o;
  o += fmt::format(R"svg(<g clip-path="url(#{})" stroke="#555" stroke-width="1" stroke-dasharray="5 3">)svg", clip);
  for (const auto& g : chart.guides) {
    if (g.vertical)
      o += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)", num(px(g.value)), num(top), num(top + ph));
    else
      o += fmt::format(R"(<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>)", num(py(g.value)), num(left), num(left + pw));
  }
  // Labels with a white halo, readable where a curve passes under them.
  o += fmt::format(R"(</g>
<g fill="#444" stroke="#fff" stroke-width="3" paint-order="stroke" font-size="{}">)",
                   num(small_font));
  for (const auto& g : chart.guides) {
    if (g.label.empty()) continue;
    if (g.vertical && px(g.value) > left + 0.7 * pw)  // near the right edge: label to the left of the line
      o += fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", num(px(g.value) - 3), num(top + 11),
                       xml_escape(g.label));
    else if (g.vertical)
      o += fmt::format(R"(<text x="{}" y="{}">{}</text>)", num(px(g.value) + 3), num(top + 11), xml_escape(g.label));
    else
      o += fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", num(left + pw - 3), num(py(g.value) - 4),
                       xml_escape(g.label));
  }
  o += "</g>\n";
  return o;
}

// The legend beside the plot, top aligned, from x = lx.
std::string legend_svg(const Chart& chart, const std::vector<std::string>& colour_of, double lx, double top) {
  std::string o;
  o += "<g>";
  for (std::size_t k = 0, row = 0; k < chart.series.size(); ++k) {
    const auto& s = chart.series[k];
    if (s.label.empty()) continue;
    const double y = top + 8 + legend_row * static_cast<double>(row++);
    o += fmt::format(R"(<line x1="{0}" y1="{2}" x2="{1}" y2="{2}" stroke="{3}" stroke-width="2"{4}/>)", num(lx),
                     num(lx + legend_swatch), num(y), colour_of[k], s.dashed ? R"( stroke-dasharray="6 3")" : "");
    o += fmt::format(R"(<text x="{}" y="{}" fill="#222">{}</text>)", num(lx + legend_swatch + 6), num(y + 4),
                     xml_escape(s.label));
  }
  o += "</g>\n";
  return o;
}

}  // namespace

const std::vector<std::string>& categorical_colours() {
  static const std::vector<std::string> colours{"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                                "#E69F00", "#56B4E9", "#000000", "#999999"};
  return colours;
}

std::vector<std::string> sequential_colours(std::size_t n) {
  // Matplotlib's plasma, cut before its pale yellow end (unreadable on white).
  static constexpr std::array<std::array<double, 3>, 5> stops{
      {{13, 8, 135}, {126, 3, 168}, {204, 71, 120}, {240, 126, 74}, {247, 172, 52}}};
  std::vector<std::string> out;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = n > 1 ? double(k) / double(n - 1) * (stops.size() - 1) : 0.0;
    const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - double(i);
    std::array<int, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = static_cast<int>(std::lround(stops[i][d] * (1 - f) + stops[i + 1][d] * f));
    out.push_back(fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]));
  }
  return out;
}

// Vertical error bars with caps, one per point with a finite error.
template <class Px, class Py>
std::string error_bars_svg(const ErrorBars& b, Px&& px, Py&& py) {
  std::string o;
  const std::size_t n = std::min({b.x.size(), b.y.size(), b.error.size()});
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(b.x[i]) || !std::isfinite(b.y[i]) || !std::isfinite(b.error[i])) continue;
    const double x = px(b.x[i]), lo = py(b.y[i] - b.error[i]), hi = py(b.y[i] + b.error[i]);
    o += fmt::format(
        R"(<path class="error-bar" stroke="{0}" stroke-width="1.2" fill="none" d="M{1},{2}V{3}M{4},{2}h7M{4},{3}h7"/>)"
        R"(<circle cx="{1}" cy="{5}" r="2.2" fill="{0}" stroke="none"/>)",
        b.colour, num(x), num(lo), num(hi), num(x - 3.5), num(py(b.y[i])));
  }
  return o;
}

std::string render_svg(const Chart& chart) {
  Range xr, yr;
  bool has_points = false;
  for (const auto& s : chart.series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    for (std::size_t i = 0; i < n; ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) xr.add(s.x[i]), yr.add(s.y[i]), has_points = true;
  }
  for (const auto& b : chart.error_bars)
    for (std::size_t i = 0; i < std::min({b.x.size(), b.y.size(), b.error.size()}); ++i)
      if (std::isfinite(b.error[i])) xr.add(b.x[i]), yr.add(b.y[i] - b.error[i]), yr.add(b.y[i] + b.error[i]);
  for (double v : chart.x_include) xr.add(v);
  for (double v : chart.y_include) yr.add(v);
  for (const auto& g : chart.guides) (g.vertical ? xr : yr).add(g.value);
  if (xr.empty()) xr.add(0), xr.add(1);
  if (yr.empty()) yr.add(0), yr.add(1);
  const NiceScale xs = tight_scale(xr.lo, xr.hi), ys = tight_scale(yr.lo, yr.hi);

  // Margins from the labels they hold.
  double y_tick_width = 0;
  for (double v : ys.ticks) y_tick_width = std::max(y_tick_width, svg::text_width(tick_label(v, ys.decimals), font));
  std::vector<const Series*> legend;
  double legend_width = 0;
  for (const auto& s : chart.series)
    if (!s.label.empty()) legend.push_back(&s), legend_width = std::max(legend_width, svg::text_width(s.label, font));
  const double left = y_tick_width + tick_length + 30, bottom = 44, top = 12;
  const double right = legend.empty() ? 16 : legend_width + legend_swatch + 30;
  const double W = chart.width, H = chart.height, pw = W - left - right, ph = H - top - bottom;
  const XAxis x_axis{xs, left, top, pw, ph};
  auto px = [&](double x) { return x_axis.px(x); };
  auto py = [&](double y) { return top + (ys.hi - y) / (ys.hi - ys.lo) * ph; };
  const std::string clip = svg::unique_id("plot");

  std::string o = fmt::format(
      R"(<svg class="chart" viewBox="0 0 {} {}" width="{}" height="{}" role="img" font-family="{}" font-size="{}">)"
      "\n<title>{}</title>\n",
      W, H, W, H, svg::font_family, num(font), xml_escape(chart.title));
  o += fmt::format(R"(<defs><clipPath id="{}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath></defs>)"
                   "\n",
                   clip, num(left), num(top), num(pw), num(ph));
  // Grid and ticks.
  o += R"(<g stroke="#e4e4e4" stroke-width="1">)" + x_axis.grid();
  for (double v : ys.ticks)
    o += fmt::format(R"(<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>)", num(py(v)), num(left), num(left + pw));
  o += "</g>\n<g stroke=\"#222\" stroke-width=\"1\">" + x_axis.ticks();
  for (double v : ys.ticks)
    o += fmt::format(R"(<line x1="{1}" y1="{0}" x2="{2}" y2="{0}"/>)", num(py(v)), num(left - tick_length), num(left));
  o += x_axis.frame() + "</g>\n<g fill=\"#222\">" + x_axis.labels();
  for (double v : ys.ticks)
    o += fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", num(left - tick_length - 3), num(py(v) + 4),
                     tick_label(v, ys.decimals));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)", num(left + pw / 2), num(H - 6),
                   xml_escape(chart.x_label));
  o += fmt::format(R"svg(<text transform="translate({},{}) rotate(-90)" text-anchor="middle">{}</text>)svg", num(13),
                   num(top + ph / 2), xml_escape(chart.y_label));
  o += "</g>\n";

  o += guides_svg(chart, px, py, {left, top, pw, ph}, clip);

  // Data.
  std::size_t next_colour = 0;
  std::vector<std::string> colour_of(chart.series.size());
  for (std::size_t k = 0; k < chart.series.size(); ++k)
    colour_of[k] = chart.series[k].colour.empty() ? categorical_colours()[next_colour++ % categorical_colours().size()]
                                                  : chart.series[k].colour;
  o += fmt::format(R"svg(<g clip-path="url(#{})" fill="none" stroke-linejoin="round">)svg", clip);
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const auto& s = chart.series[k];
    const std::string dash = s.dashed ? R"( stroke-dasharray="6 3")" : "";
    for (const auto& points : pieces(s, [&](double x, double y) { return std::pair{px(x), py(y)}; }))
      o += fmt::format(R"(<polyline stroke="{}" stroke-width="{}"{} points="{}"/>)", colour_of[k], num(s.width), dash,
                       points);
    if (s.markers) {
      const std::size_t n = std::min(s.x.size(), s.y.size());
      for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          o += fmt::format(R"(<circle cx="{}" cy="{}" r="2.6" fill="{}" stroke="none"/>)", num(px(s.x[i])),
                           num(py(s.y[i])), colour_of[k]);
    }
  }
  for (const auto& b : chart.error_bars) o += error_bars_svg(b, px, py);
  o += "</g>\n";
  if (!has_points)
    o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" fill="#777">{}</text>)", num(left + pw / 2),
                     num(top + ph / 2), xml_escape(chart.empty_note));

  if (!legend.empty()) o += legend_svg(chart, colour_of, left + pw + 14, top);
  o += "</svg>";
  return o;
}

std::string render_svg(const BarChart& chart) {
  Range xr;
  for (const auto& b : chart.bars) xr.add(b.start), xr.add(b.end);
  xr.add(chart.open_end);
  for (double v : chart.x_include) xr.add(v);
  for (const auto& g : chart.guides)
    if (g.vertical) xr.add(g.value);
  if (xr.empty()) xr.add(0), xr.add(1);
  const NiceScale xs = tight_scale(xr.lo, xr.hi);

  double label_width = 0;
  for (const auto& b : chart.bars) label_width = std::max(label_width, svg::text_width(b.label, font));
  const double rows = static_cast<double>(std::max<std::size_t>(chart.bars.size(), 1));
  const double left = label_width + tick_length + 12, right = 16, top = 20, bottom = 44;
  const double W = chart.width, pw = W - left - right, ph = rows * chart.row_height, H = top + ph + bottom;
  const XAxis x_axis{xs, left, top, pw, ph};
  auto px = [&](double x) { return x_axis.px(x); };
  auto row_y = [&](std::size_t k) { return top + (static_cast<double>(k) + 0.5) * chart.row_height; };
  const std::string clip = svg::unique_id("plot"), fade = svg::unique_id("fade");

  std::string o = fmt::format(
      R"(<svg class="chart bars" viewBox="0 0 {} {}" width="{}" height="{}" role="img" font-family="{}" font-size="{}">)"
      "\n<title>{}</title>\n",
      W, num(H), W, num(H), svg::font_family, num(font), xml_escape(chart.title));
  o += fmt::format(R"(<defs><clipPath id="{}"><rect x="{}" y="{}" width="{}" height="{}"/></clipPath>)", clip,
                   num(left), num(top), num(pw), num(ph));
  o += fmt::format(R"(<linearGradient id="{0}" x1="0" x2="1" y1="0" y2="0"><stop offset="0" stop-color="{1}"/>)"
                   R"(<stop offset="1" stop-color="{1}" stop-opacity="0.1"/></linearGradient></defs>)"
                   "\n",
                   fade, chart.colour);
  // Grid, axes, ticks and labels.
  o += R"(<g stroke="#e4e4e4" stroke-width="1">)" + x_axis.grid();
  o += "</g>\n<g stroke=\"#222\" stroke-width=\"1\">" + x_axis.ticks() + x_axis.frame();
  o += "</g>\n<g fill=\"#222\">" + x_axis.labels();
  for (std::size_t k = 0; k < chart.bars.size(); ++k)
    o += fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", num(left - tick_length - 2),
                     num(row_y(k) + 4), xml_escape(chart.bars[k].label));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)", num(left + pw / 2), num(H - 6),
                   xml_escape(chart.x_label));
  o += "</g>\n";

  // The bars; an unended one fades out towards open_end and has no right edge.
  const double thick = 0.62 * chart.row_height, open_end = std::isfinite(chart.open_end) ? chart.open_end : xs.hi;
  o += fmt::format(R"svg(<g clip-path="url(#{})">)svg", clip);
  for (std::size_t k = 0; k < chart.bars.size(); ++k) {
    const Bar& b = chart.bars[k];
    const double y0 = row_y(k) - thick / 2;
    if (!std::isfinite(b.start)) {
      o += fmt::format(R"(<g class="bar never"><text x="{}" y="{}" fill="#777" font-size="{}">{}</text></g>)",
                       num(left + 4), num(row_y(k) + 4), num(small_font), xml_escape(chart.never_started));
      continue;
    }
    const bool open = !std::isfinite(b.end);
    const double x0 = px(b.start), x1 = std::max(px(open ? open_end : b.end), x0 + 1.0);
    const std::string tip =
        fmt::format("{}: {:g} to {}", b.label, b.start, open ? "not finished" : fmt::format("{:g}", b.end));
    if (open)
      o += fmt::format(
          R"svg(<g class="bar open"><title>{0}</title><rect x="{1}" y="{2}" width="{3}" height="{4}" fill="url(#{5})"/>)svg"
          R"(<path d="M{6} {2}H{1}V{7}H{6}" fill="none" stroke="{8}" stroke-width="1"/></g>)",
          xml_escape(tip), num(x0), num(y0), num(x1 - x0), num(thick), fade, num(x1), num(y0 + thick), chart.colour);
    else
      o += fmt::format(R"(<g class="bar"><title>{}</title><rect x="{}" y="{}" width="{}" height="{}" fill="{}"/></g>)",
                       xml_escape(tip), num(x0), num(y0), num(x1 - x0), num(thick), chart.colour);
  }
  o += "</g>\n";
  // Reference lines over the bars, labelled above the plot.
  o += R"(<g stroke="#555" stroke-width="1" stroke-dasharray="5 3">)";
  for (const auto& g : chart.guides)
    if (g.vertical)
      o += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)", num(px(g.value)), num(top - 4), num(top + ph));
  o += fmt::format(R"(</g><g fill="#444" font-size="{}">)", num(small_font));
  for (const auto& g : chart.guides)
    if (g.vertical && !g.label.empty())
      o += fmt::format(R"(<text x="{}" y="{}" text-anchor="{}">{}</text>)", num(px(g.value)), num(top - 7),
                       px(g.value) > left + 0.7 * pw   ? "end"
                       : px(g.value) < left + 0.3 * pw ? "start"
                                                       : "middle",
                       xml_escape(g.label));
  o += "</g>\n";
  if (chart.bars.empty())
    o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" fill="#777">no bars</text>)", num(left + pw / 2),
                     num(row_y(0) + 4));
  o += "</svg>";
  return o;
}

}  // namespace frostwall::report
