#include "report/layout_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <numbers>

#include "io/xml_escape.hpp"
#include "report/nice_scale.hpp"
#include "report/svg.hpp"

namespace frostwall::report {

using io::xml_escape;
using svg::num;

std::string layout_svg(const LayoutDrawing& dw, int size) {
  double ring = 0.0;
  for (const auto& p : dw.pipes) ring = std::max(ring, std::hypot(p.x, p.y));
  const double excavation = dw.section->shaft.excavation_radius.value_or(0.0);
  // Show the pipes with room around them; the far field is usually far off.
  const double extent = std::max({1.25 * ring, 1.1 * excavation, 1.0});
  const double c = size / 2.0, scale = (size / 2.0 - 14) / extent;
  auto X = [&](double x) { return c + x * scale; };
  auto Y = [&](double y) { return c - y * scale; };

  std::string o = fmt::format(
      R"(<svg class="layout" viewBox="0 0 {0} {0}" width="{0}" height="{0}" role="img" font-family="{1}" font-size="12">)"
      "<title>layout of the freeze pipes: plan view</title>",
      size, svg::font_family);
  const double R = dw.section->outer_radius;
  if (R * scale < size / 2.0 * 1.4)
    o += fmt::format(R"(<circle cx="{0}" cy="{0}" r="{1}" fill="none" stroke="#999" stroke-dasharray="2 3"/>)", num(c),
                     num(R * scale));
  if (excavation > 0)
    o += fmt::format(R"(<circle cx="{0}" cy="{0}" r="{1}" fill="#ece8e0" stroke="#333" stroke-width="1.2"/>)"
                     R"(<text x="{0}" y="{2}" text-anchor="middle" fill="#333">excavation</text>)"
                     R"(<text x="{0}" y="{3}" text-anchor="middle" fill="#333">r = {4} m</text>)",
                     num(c), num(excavation * scale), num(c + 0.35 * excavation * scale),
                     num(c + 0.35 * excavation * scale + 15), num(excavation));

  // The simulated wedge, shaded, out to the drawing's edge.
  if (dw.wedge.mirror_lines > 0) {
    const double r = extent * 0.98, a0 = dw.wedge.start, a1 = dw.wedge.start + dw.wedge.angle;
    o += fmt::format(
        R"(<path d="M{} {} L{} {} A{} {} 0 {} 0 {} {} Z" fill="#0072B2" fill-opacity="0.16" stroke="#0072B2" stroke-width="0.8"/>)",
        num(X(0)), num(Y(0)), num(X(r * std::cos(a0))), num(Y(r * std::sin(a0))), num(r * scale), num(r * scale),
        dw.wedge.angle > std::numbers::pi ? 1 : 0, num(X(r * std::cos(a1))), num(Y(r * std::sin(a1))));
  }
  // OA and OB, labelled at their ends.
  const double ray = extent * 1.02;
  if (dw.thinnest_ray) {
    const double a = *dw.thinnest_ray;
    o += fmt::format(R"(<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="#D55E00" stroke-width="1.1"/>)"
                     R"(<text x="{}" y="{}" text-anchor="middle" fill="#D55E00">thinnest</text>)",
                     num(X(0)), num(Y(0)), num(X(0.97 * ray * std::cos(a))), num(Y(0.97 * ray * std::sin(a))),
                     num(X(ray * std::cos(a))), num(Y(ray * std::sin(a)) + 4));
  }
  for (const auto& [angle, name] : {std::pair{dw.OA, "A"}, std::pair{dw.OB, "B"}}) {
    if (dw.thinnest_ray) break;
    o += fmt::format(R"(<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="#D55E00" stroke-width="1.1"/>)", num(X(0)),
                     num(Y(0)), num(X(0.97 * ray * std::cos(angle))), num(Y(0.97 * ray * std::sin(angle))));
    // Labels go beside the ray's end, pushed apart when OA and OB are close.
    const double side = name[0] == 'A' ? -1.0 : 1.0;
    const double nx = -std::sin(angle) * side * 9, ny = std::cos(angle) * side * 9;
    o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" fill="#D55E00" font-weight="bold">{}</text>)",
                     num(X(ray * std::cos(angle)) + nx), num(Y(ray * std::sin(angle)) - ny + 4), name);
  }
  if (!dw.thinnest_ray)
    o += fmt::format(R"(<text x="{}" y="{}" fill="#D55E00" font-weight="bold">O</text>)", num(c + 4), num(c + 14));
  // Pipes to scale, at least visible; the design positions faintly beneath.
  const double pr = std::max(0.5 * dw.section->pipe.diameter * scale, 1.8);
  o += R"(<g fill="none" stroke="#888" stroke-width="0.8" stroke-dasharray="1.5 1.5">)";
  for (const auto& p : dw.design_pipes)
    o += fmt::format(R"(<circle cx="{}" cy="{}" r="{}"/>)", num(X(p.x)), num(Y(p.y)), num(pr + 1));
  o += R"(</g><g fill="#0b3c73">)";
  for (const auto& p : dw.pipes)
    if (!p.failed)
      o += fmt::format(R"(<circle cx="{}" cy="{}" r="{}"><title>{} (pipe {})</title></circle>)", num(X(p.x)),
                       num(Y(p.y)), num(pr), xml_escape(p.label), p.number);
  o += "</g>";
  for (const auto& p : dw.pipes)
    if (p.failed)
      o += fmt::format(R"(<g stroke="#c0392b" stroke-width="1.4" fill="none"><circle cx="{0}" cy="{1}" r="{2}"/>)"
                       R"(<path d="M{3} {4} l{5} {5} M{3} {6} l{5} -{5}"/><title>pipe {7}: failed</title></g>)",
                       num(X(p.x)), num(Y(p.y)), num(pr + 1.5), num(X(p.x) - pr - 2), num(Y(p.y) - pr - 2),
                       num(2 * pr + 4), num(Y(p.y) + pr + 2), p.number);
  if (dw.numbers && dw.pipes.size() <= 80)
    for (const auto& p : dw.pipes) {
      const double r = std::hypot(p.x, p.y), a = std::atan2(p.y, p.x);
      const double off = (pr + 8) / scale;  // outward, beside the pipe
      const double lx = r > 0 ? (r + off) * std::cos(a) : p.x + off, ly = r > 0 ? (r + off) * std::sin(a) : p.y;
      o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" font-size="9" fill="{}">{}</text>)", num(X(lx)),
                       num(Y(ly) + 3), p.failed ? "#c0392b" : "#555", p.number);
    }
  for (const auto& s : dw.sensors)
    o += fmt::format(
        R"(<path d="M{} {} l-4 6 h8 z" fill="#009E73"/><text x="{}" y="{}" fill="#006b4e" font-size="11">{}</text>)",
        num(X(s.x)), num(Y(s.y) - 3), num(X(s.x) + 6), num(Y(s.y) - 4), xml_escape(s.name));
  // Scale bar.
  const NiceScale bar = nice_scale(0.0, extent / 2.5, 1);
  const double len = bar.step * scale;
  o += fmt::format(R"(<path d="M10 {0} v5 h{1} v-5" fill="none" stroke="#111" stroke-width="1.5"/>)"
                   R"(<text x="{2}" y="{3}" text-anchor="middle" font-size="11">{4} m</text>)",
                   size - 14, num(len), num(10 + len / 2), size - 13, tick_label(bar.step, bar.decimals));
  o += "</svg>";
  return o;
}

std::string rectangle_svg(const project::Rectangle& r, int width) {
  // Drawn to scale when the strip is not too thin, else stretched to be seen.
  const double w = width - 140.0;
  const double h = std::clamp(w * r.height / r.width, 24.0, 200.0);
  auto side = [](const project::SideCondition& s) {
    if (std::holds_alternative<project::Adiabatic>(s)) return std::string("adiabatic");
    const auto& t = std::get<project::FixedTemperature>(s).temperature;
    return t.constant() ? fmt::format("{} °C", t.points.front().second) : std::string("scheduled T");
  };
  const double H = h + 80, x0 = 70, y0 = 36;
  std::string o = fmt::format(
      R"(<svg class="layout" viewBox="0 0 {0} {1}" width="{0}" height="{1}" role="img" font-family="{2}" font-size="12">)"
      "<title>plain geometry: rectangle</title>",
      width, num(H), svg::font_family);
  o += fmt::format(R"(<rect x="{}" y="{}" width="{}" height="{}" fill="#f3efe6" stroke="#333"/>)", x0, y0, num(w),
                   num(h));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="end">{}</text>)", x0 - 6, num(y0 + h / 2 + 4),
                   xml_escape(side(r.left)));
  o += fmt::format(R"(<text x="{}" y="{}">{}</text>)", num(x0 + w + 6), num(y0 + h / 2 + 4), xml_escape(side(r.right)));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)", num(x0 + w / 2), y0 - 8,
                   xml_escape(side(r.top)));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle">{}</text>)", num(x0 + w / 2), num(y0 + h + 18),
                   xml_escape(side(r.bottom)));
  o += fmt::format(R"(<text x="{}" y="{}" text-anchor="middle" fill="#555">{:g} m × {:g} m</text></svg>)",
                   num(x0 + w / 2), num(y0 + h + 38), r.width, r.height);
  return o;
}

}  // namespace frostwall::report
