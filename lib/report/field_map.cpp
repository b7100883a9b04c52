#include "report/field_map.hpp"

#include <cmath>
#include <fmt/core.h>
#include <limits>
#include <numbers>

#include "io/xml_escape.hpp"
#include "post/field_sampler.hpp"
#include "project/project.hpp"
#include "report/nice_scale.hpp"
#include "report/svg.hpp"
#include "sph/kernel.hpp"

namespace frostwall::report {

using Vec2 = particles::Vec<2>;
using svg::num;

struct FieldMap::Probe {
  std::vector<Vec2> position;  // the particles, in the snapshot's order
  std::unique_ptr<sph::Kernel> kernel;
  std::unique_ptr<post::PointProbe> probe;
  std::vector<std::size_t> pixel;  // raster index of each probe point
};

namespace {

particles::ParticleSet<2> particle_set(const FieldSnapshot& s, const WedgeSymmetry& w, bool mirrored, double spacing) {
  particles::ParticleSet<2> P;
  for (std::size_t i = 0; i < s.position.size(); ++i) P.add(s.position[i], s.volume[i], s.boundary[i]);
  P.order_free_first();  // already so in the files; a no-op kept for safety
  P.spacing = spacing;
  // The wedge sides as the solver had them (geometry/shaft_section.cpp).
  if (mirrored && w.mirror_lines > 0) {
    P.mirrors.push_back({Vec2::Zero(), Vec2(-std::sin(w.start), std::cos(w.start))});
    if (w.mirror_lines > 1) {
      const double b = w.start + w.angle;
      P.mirrors.push_back({Vec2::Zero(), Vec2(-std::sin(b), std::cos(b))});
    }
  }
  return P;
}

// Pixels in the domain with no particle in reach (the wedge's apex on the
// shaft axis, a few pixels wide) take the mean of their valued neighbours,
// a few rings deep, so the map has no pinholes.
void fill_small_holes(std::vector<double>& value, const std::vector<char>& inside, int n) {
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<double> next = value;
    bool changed = false;
    for (int row = 0; row < n; ++row)
      for (int col = 0; col < n; ++col) {
        const std::size_t k = std::size_t(row) * std::size_t(n) + std::size_t(col);
        if (!inside[k] || std::isfinite(value[k])) continue;
        double sum = 0.0;
        int count = 0;
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int r = row + dr, c = col + dc;
            if (r < 0 || c < 0 || r >= n || c >= n) continue;
            const double v = value[std::size_t(r) * std::size_t(n) + std::size_t(c)];
            if (std::isfinite(v)) sum += v, ++count;
          }
        if (count > 0) next[k] = sum / count, changed = true;
      }
    value.swap(next);
    if (!changed) break;
  }
}

}  // namespace

bool field_is_wedge(const FieldSnapshot& s, const WedgeSymmetry& w, double spacing) {
  if (w.mirror_lines <= 0) return false;
  // A free particle clearly outside the wedge: the field is the full ring.
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    if (s.boundary[i] >= 0) continue;
    const Vec2& x = s.position[i];
    if ((w.fold(x) - x).norm() > 2.0 * spacing) return false;
  }
  return true;
}

namespace {

// The end of an open curve moved onto a wedge side within `snap` of it.
void snap_to_sides(post::Polyline& c, const WedgeSymmetry& w, double snap) {
  if (c.closed || c.points.size() < 2 || w.mirror_lines <= 0) return;
  for (Vec2* end : {&c.points.front(), &c.points.back()})
    for (double side : {w.start, w.start + w.angle}) {
      const Vec2 u(std::cos(side), std::sin(side));
      const double along = end->dot(u);
      const Vec2 foot = along * u;
      if (along > 0 && (*end - foot).norm() < snap) {
        *end = foot;
        break;
      }
    }
}

}  // namespace

std::vector<post::Polyline> unfold(const std::vector<post::Polyline>& wedge_curves, const WedgeSymmetry& w,
                                   double snap) {
  std::vector<post::Polyline> curves = wedge_curves, out;
  for (auto& c : curves) snap_to_sides(c, w, snap);
  out.reserve(curves.size() * w.copies());
  for (std::size_t g = 0; g < w.copies(); ++g)
    for (const auto& c : curves) {
      post::Polyline copy{{}, c.closed};
      copy.points.reserve(c.points.size());
      for (const auto& x : c.points) copy.points.push_back(w.apply(g, x));
      out.push_back(std::move(copy));
    }
  return out;
}

FieldMap::FieldMap(const FieldSnapshot& particles, const WedgeSymmetry& symmetry, const std::string& kernel, double h,
                   double spacing, const MapWindow& window, double domain_radius)
    : probe_(std::make_unique<Probe>()), window_(window), spacing_(spacing) {
  const bool wedge = field_is_wedge(particles, symmetry, spacing);
  symmetry_ = wedge ? symmetry : WedgeSymmetry{};
  probe_->kernel = sph::make_kernel<2>(kernel == "cubic_spline" ? project::KernelKind::cubic_spline
                                                                : project::KernelKind::wendland_c2);
  probe_->position = particles.position;
  const auto P = particle_set(particles, symmetry_, wedge, spacing);
  const post::FieldSampler sampler(P, *probe_->kernel, h);
  std::vector<Vec2> where;
  const int n = window.pixels;
  const double d = window.size / n;
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col) {
      const Vec2 x(window.x0 + (col + 0.5) * d, window.y0 + window.size - (row + 0.5) * d);
      if (domain_radius > 0.0 && x.norm() > domain_radius) continue;
      where.push_back(symmetry_.fold(x));
      probe_->pixel.push_back(std::size_t(row) * std::size_t(n) + std::size_t(col));
    }
  probe_->probe = std::make_unique<post::PointProbe>(sampler, std::move(where));
}

FieldMap::~FieldMap() = default;

RgbaImage FieldMap::raster(const std::vector<double>& temperature, const ColourScale& colours) const {
  const std::vector<double> T = (*probe_->probe)(temperature);
  const int n = window_.pixels;
  std::vector<double> value(std::size_t(n) * std::size_t(n), std::numeric_limits<double>::quiet_NaN());
  std::vector<char> inside(value.size(), 0);
  for (std::size_t k = 0; k < T.size(); ++k) value[probe_->pixel[k]] = T[k], inside[probe_->pixel[k]] = 1;
  fill_small_holes(value, inside, n);
  return paint(value, n, colours);
}

RgbaImage paint(const std::vector<double>& values, int pixels, const ColourScale& colours) {
  RgbaImage image(pixels, pixels);
  for (std::size_t k = 0; k < values.size() && k < image.pixels.size() / 4; ++k) {
    if (!std::isfinite(values[k])) continue;
    const auto c = colours(values[k]);
    std::uint8_t* p = image.pixels.data() + 4 * k;
    p[0] = c[0], p[1] = c[1], p[2] = c[2], p[3] = 255;
  }
  return image;
}

RgbaImage FieldMap::nearest_raster(const std::vector<std::array<std::uint8_t, 3>>& colours, double reach) const {
  RgbaImage image(window_.pixels, window_.pixels);
  const auto& x = probe_->position;
  if (x.empty() || colours.size() != x.size()) return image;
  // The particles in square cells of side `radius`: the nearest one within
  // it lies in the pixel's cell or one of the eight around.
  const double radius = reach * (spacing_ > 0.0 ? spacing_ : window_.size / window_.pixels);
  Vec2 lo = x.front(), hi = x.front();
  for (const auto& p : x) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const long nx = long((hi[0] - lo[0]) / radius) + 1, ny = long((hi[1] - lo[1]) / radius) + 1;
  std::vector<std::vector<std::size_t>> cell(std::size_t(nx * ny));
  auto cell_of = [&](const Vec2& p, long& cx, long& cy) {
    cx = long(std::floor((p[0] - lo[0]) / radius)), cy = long(std::floor((p[1] - lo[1]) / radius));
  };
  for (std::size_t i = 0; i < x.size(); ++i) {
    long cx, cy;
    cell_of(x[i], cx, cy);
    cell[std::size_t(std::min(cy, ny - 1) * nx + std::min(cx, nx - 1))].push_back(i);
  }
  const int n = window_.pixels;
  const double d = window_.size / n;
  for (const std::size_t k : probe_->pixel) {
    const long row = long(k) / n, col = long(k) % n;
    const Vec2 p = symmetry_.fold(Vec2(window_.x0 + (col + 0.5) * d, window_.y0 + window_.size - (row + 0.5) * d));
    long cx, cy;
    cell_of(p, cx, cy);
    double best = radius * radius;
    std::size_t nearest = x.size();
    for (long j = std::max(cy - 1, 0L); j <= std::min(cy + 1, ny - 1); ++j)
      for (long i = std::max(cx - 1, 0L); i <= std::min(cx + 1, nx - 1); ++i)
        for (const std::size_t q : cell[std::size_t(j * nx + i)])
          if (const double r2 = (x[q] - p).squaredNorm(); r2 <= best) best = r2, nearest = q;
    if (nearest == x.size()) continue;
    std::uint8_t* out = image.pixels.data() + 4 * k;
    out[0] = colours[nearest][0], out[1] = colours[nearest][1], out[2] = colours[nearest][2], out[3] = 255;
  }
  return image;
}

std::string FieldMap::html(const std::vector<double>& temperature, const ColourScale& colours,
                           const std::vector<post::Polyline>& fronts, bool fronts_whole, const MapOverlay& overlay,
                           const std::string& title) const {
  return html(raster(temperature, colours), "temperature", fronts, fronts_whole, overlay, title);
}

std::string FieldMap::html(const RgbaImage& image, const std::string& what, const std::vector<post::Polyline>& fronts,
                           bool fronts_whole, const MapOverlay& overlay, const std::string& title) const {
  return map_html(image, window_, what, fronts_whole ? fronts : unfold(fronts, symmetry_, 1.5 * spacing_), overlay,
                  title);
}

std::string map_html(const RgbaImage& image, const MapWindow& window, const std::string& what,
                     const std::vector<post::Polyline>& fronts, const MapOverlay& overlay, const std::string& title) {
  const int n = window.pixels;
  const double scale = n / window.size;  // px per metre
  auto px = [&](const Vec2& x) {
    return std::pair{(x[0] - window.x0) * scale, (window.y0 + window.size - x[1]) * scale};
  };
  // The raster is an <img>; the vectors lie over it in an SVG of the same size.
  std::string o = fmt::format(R"(<div class="map"><img src="{}" width="{}" height="{}" alt="{} map, {}">)",
                              png_data_uri(image), n, n, io::xml_escape(what), io::xml_escape(title));
  o += fmt::format(
      R"(<svg viewBox="0 0 {0} {0}" width="{0}" height="{0}" role="img" font-family="{1}" font-size="13"><title>{2}</title>)",
      n, svg::font_family, io::xml_escape(title));
  if (overlay.domain_radius > 0.0) {
    const auto [cx, cy] = px(Vec2::Zero());
    o += fmt::format(R"(<circle cx="{}" cy="{}" r="{}" fill="none" stroke="#888" stroke-width="0.8"/>)", num(cx),
                     num(cy), num(overlay.domain_radius * scale));
  }
  if (overlay.excavation_radius > 0.0) {
    const auto [cx, cy] = px(Vec2::Zero());
    o += fmt::format(
        R"(<circle cx="{}" cy="{}" r="{}" fill="none" stroke="#333" stroke-width="1" stroke-dasharray="5 3"/>)",
        num(cx), num(cy), num(overlay.excavation_radius * scale));
  }
  if (overlay.lining_radius > 0.0) {
    const auto [cx, cy] = px(Vec2::Zero());
    o += fmt::format(
        R"(<circle cx="{}" cy="{}" r="{}" fill="none" stroke="#333" stroke-width="1" stroke-dasharray="1.5 2.5"/>)",
        num(cx), num(cy), num(overlay.lining_radius * scale));
  }
  // Frozen front: a white halo under a black line reads on blue and on red.
  std::string d;
  for (const auto& c : fronts) {
    if (c.points.size() < 2) continue;
    for (std::size_t k = 0; k < c.points.size(); ++k) {
      const auto [x, y] = px(c.points[k]);
      d += k == 0 ? 'M' : 'L';
      d += num(x) + " " + num(y);
    }
    if (c.closed) d += "Z";
  }
  if (!d.empty())
    o += fmt::format(R"(<path d="{0}" fill="none" stroke="#fff" stroke-width="2.6" stroke-opacity="0.7"/>)"
                     R"(<path d="{0}" fill="none" stroke="#000" stroke-width="1.1"/>)",
                     d);
  if (!overlay.arrows.empty()) {  // shaft and a head of two strokes, under the pipes
    std::string a;
    for (const auto& arrow : overlay.arrows) {
      const auto [x0, y0] = px(Vec2(arrow.x, arrow.y));
      const auto [x1, y1] = px(Vec2(arrow.x + arrow.dx, arrow.y + arrow.dy));
      const double len = std::hypot(x1 - x0, y1 - y0);
      if (len < 1.0) continue;
      const double ux = (x1 - x0) / len, uy = (y1 - y0) / len, head = std::min(4.0, 0.4 * len);
      a += fmt::format("M{} {}L{} {}M{} {}L{} {}L{} {}", num(x0), num(y0), num(x1), num(y1),
                       num(x1 - head * (ux - 0.5 * uy)), num(y1 - head * (uy + 0.5 * ux)), num(x1), num(y1),
                       num(x1 - head * (ux + 0.5 * uy)), num(y1 - head * (uy - 0.5 * ux)));
    }
    o += fmt::format(R"(<path d="{0}" fill="none" stroke="#000" stroke-width="2.2" stroke-opacity="0.5"/>)"
                     R"(<path d="{0}" fill="none" stroke="#fff" stroke-width="1"/>)",
                     a);
  }
  o += R"(<g fill="#111" stroke="#fff" stroke-width="0.6">)";
  for (const auto& p : overlay.pipes) {
    const auto [x, y] = px(Vec2(p.x, p.y));
    if (x < -5 || y < -5 || x > n + 5 || y > n + 5) continue;
    o += fmt::format(R"(<circle cx="{}" cy="{}" r="{}"/>)", num(x), num(y), num(std::max(p.r * scale, 1.6)));
  }
  o += "</g>";
  // Title and a scale bar of a round length, about a fifth of the window.
  const NiceScale bar = nice_scale(0.0, window.size / 5.0, 1);
  const double metres = bar.step, len = metres * scale;
  o += fmt::format(
      R"(<rect x="6" y="6" width="{}" height="20" fill="#fff" fill-opacity="0.85"/><text x="11" y="21">{}</text>)",
      num(svg::text_width(title, 13) + 12), io::xml_escape(title));
  o += fmt::format(R"(<rect x="6" y="{0}" width="{1}" height="26" fill="#fff" fill-opacity="0.85"/>)"
                   R"(<path d="M12 {2} v5 h{3} v-5" fill="none" stroke="#111" stroke-width="1.5"/>)"
                   R"(<text x="{4}" y="{5}" text-anchor="middle" font-size="11">{6} m</text>)",
                   n - 32, num(len + 12), n - 12, num(len), num(12 + len / 2), n - 16,
                   tick_label(metres, bar.decimals));
  o += fmt::format(R"(<rect x="0.5" y="0.5" width="{0}" height="{0}" fill="none" stroke="#222"/></svg></div>)", n - 1);
  return o;
}

}  // namespace frostwall::report
