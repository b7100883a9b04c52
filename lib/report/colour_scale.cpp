#include "report/colour_scale.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <vector>

#include "report/nice_scale.hpp"
#include "report/svg.hpp"

namespace frostwall::report {

namespace {

// Moreland's cool-warm (as in matplotlib's "coolwarm"), sampled at nine points.
constexpr std::array<std::array<double, 3>, 9> table{{{59, 76, 192},
                                                      {98, 130, 234},
                                                      {141, 176, 254},
                                                      {184, 208, 249},
                                                      {221, 221, 221},
                                                      {245, 196, 173},
                                                      {244, 154, 123},
                                                      {222, 96, 77},
                                                      {180, 4, 38}}};

std::string hex(const std::array<std::uint8_t, 3>& c) { return fmt::format("#{:02x}{:02x}{:02x}", c[0], c[1], c[2]); }

}  // namespace

ColourScale::ColourScale(double lo, double hi, double pivot)
    : lo_(lo), hi_(hi > lo ? hi : lo + 1.0), pivot_(pivot), diverging_(pivot > lo && pivot < hi) {}

double ColourScale::position(double T) const {
  T = std::clamp(T, lo_, hi_);
  if (!diverging_) return (T - lo_) / (hi_ - lo_);
  return T <= pivot_ ? 0.5 * (T - lo_) / (pivot_ - lo_) : 0.5 + 0.5 * (T - pivot_) / (hi_ - pivot_);
}

double ColourScale::value_at(double s) const {
  if (!diverging_) return lo_ + s * (hi_ - lo_);
  return s <= 0.5 ? lo_ + 2 * s * (pivot_ - lo_) : pivot_ + 2 * (s - 0.5) * (hi_ - pivot_);
}

std::array<std::uint8_t, 3> ColourScale::operator()(double T) const {
  const double t = position(T) * (table.size() - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(t), table.size() - 2);
  const double f = t - double(i);
  std::array<std::uint8_t, 3> c{};
  for (int d = 0; d < 3; ++d)
    c[d] = static_cast<std::uint8_t>(std::lround(table[i][d] * (1 - f) + table[i + 1][d] * f));
  return c;
}

std::string ColourScale::colour_bar_svg(int width, const std::string& quantity) const {
  const double left = 24, right = 24, bar_top = 6, bar_height = 14;
  const double w = width - left - right;
  auto px = [&](double T) { return left + (T - lo_) / (hi_ - lo_) * w; };
  const std::string id = svg::unique_id("colours");
  std::string o = fmt::format(
      R"(<svg class="colour-bar" viewBox="0 0 {0} 58" width="{0}" height="58" role="img" font-family="{1}" font-size="11">)"
      "<title>colour scale: {3}</title>"
      R"(<defs><linearGradient id="{2}" x1="0" x2="1" y1="0" y2="0">)",
      width, svg::font_family, id, quantity);
  // Stops where the table has them, placed by temperature: the bar is exact.
  for (std::size_t k = 0; k < table.size(); ++k) {
    const double s = double(k) / double(table.size() - 1);
    const double T = value_at(s);
    o += fmt::format(R"(<stop offset="{}" stop-color="{}"/>)", svg::num((T - lo_) / (hi_ - lo_)), hex((*this)(T)));
  }
  o += fmt::format(
      R"svg(</linearGradient></defs><rect x="{}" y="{}" width="{}" height="{}" fill="url(#{})" stroke="#222" stroke-width="0.8"/>)svg",
      left, bar_top, svg::num(w), bar_height, id);
  const NiceScale ticks = ticks_within(lo_, hi_, 8);
  o += R"(<g stroke="#222">)";
  for (double T : ticks.ticks)
    o += fmt::format(R"(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}"/>)", svg::num(px(T)), bar_top + bar_height,
                     bar_top + bar_height + 4);
  o += "</g><g fill=\"#222\" text-anchor=\"middle\">";
  for (double T : ticks.ticks)
    o += fmt::format(R"(<text x="{}" y="{}">{}</text>)", svg::num(px(T)), bar_top + bar_height + 16,
                     tick_label(T, ticks.decimals));
  o += fmt::format(R"(<text x="{}" y="54">{}</text></g>)", svg::num(left + w / 2), quantity);
  if (diverging_)
    o += fmt::format(R"(<path d="M{0} {1} l-4 -6 h8 z" fill="#222"><title>{2} {3}</title></path>)",
                     svg::num(px(pivot_)), bar_top,
                     quantity.starts_with("temperature") ? "freezing point" : "middle of the scale", svg::num(pivot_));
  o += "</svg>";
  return o;
}

}  // namespace frostwall::report
