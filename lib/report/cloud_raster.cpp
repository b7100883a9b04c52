#include "report/cloud_raster.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/cloud_mesh.hpp"

namespace frostwall::report {

using Vec2 = particles::Vec<2>;

CloudRaster::CloudRaster(const std::vector<Vec2>& points, double max_edge, const MapWindow& window)
    : points_(points.size()), window_(window) {
  if (points.size() < 3) return;
  const auto triangles = geometry::cloud_triangles(points, max_edge);
  triangles_ = triangles.size();
  const int n = window.pixels;
  const double d = window.size / n, top = window.y0 + window.size;
  // Pixel (row, col) has its centre at (x0 + (col + 1/2) d, top - (row + 1/2) d).
  std::vector<char> taken(std::size_t(n) * std::size_t(n), 0);
  for (const auto& t : triangles) {
    const Vec2 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    const Vec2 ab = b - a, ac = c - a;
    const double area = ab[0] * ac[1] - ab[1] * ac[0];
    if (!(std::abs(area) > 0.0)) continue;
    const Vec2 lo = a.cwiseMin(b).cwiseMin(c), hi = a.cwiseMax(b).cwiseMax(c);
    const int c0 = std::max(0, int(std::ceil((lo[0] - window.x0) / d - 0.5)));
    const int c1 = std::min(n - 1, int(std::floor((hi[0] - window.x0) / d - 0.5)));
    const int r0 = std::max(0, int(std::ceil((top - hi[1]) / d - 0.5)));
    const int r1 = std::min(n - 1, int(std::floor((top - lo[1]) / d - 0.5)));
    for (int row = r0; row <= r1; ++row)
      for (int col = c0; col <= c1; ++col) {
        const std::size_t k = std::size_t(row) * std::size_t(n) + std::size_t(col);
        if (taken[k]) continue;  // a pixel on a shared edge: its first triangle
        const Vec2 p(window.x0 + (col + 0.5) * d, top - (row + 0.5) * d);
        const Vec2 pa = a - p, pb = b - p, pc = c - p;
        const double wa = (pb[0] * pc[1] - pb[1] * pc[0]) / area;
        const double wb = (pc[0] * pa[1] - pc[1] * pa[0]) / area;
        const double wc = 1.0 - wa - wb;
        constexpr double slack = -1e-12;
        if (wa < slack || wb < slack || wc < slack) continue;
        taken[k] = 1;
        pixels_.push_back({k, t, {wa, wb, wc}});
      }
  }
}

std::vector<double> CloudRaster::sample(const std::vector<double>& values) const {
  if (values.size() != points_) throw std::invalid_argument("cloud raster: one value per point expected");
  const int n = window_.pixels;
  std::vector<double> out(std::size_t(n) * std::size_t(n), std::numeric_limits<double>::quiet_NaN());
  for (const auto& p : pixels_)
    out[p.index] = p.weight[0] * values[p.corner[0]] + p.weight[1] * values[p.corner[1]] +
                   p.weight[2] * values[p.corner[2]];
  return out;
}

RgbaImage CloudRaster::raster(const std::vector<double>& values, const ColourScale& colours) const {
  return paint(sample(values), window_.pixels, colours);
}

MapWindow window_over(const std::vector<Vec2>& points, double spacing, int pixels) {
  MapWindow window;
  window.pixels = pixels;
  if (points.empty()) return window;
  Vec2 a = points.front(), b = a;
  for (const auto& x : points) a = a.cwiseMin(x), b = b.cwiseMax(x);
  window.x0 = a[0] - 0.5 * spacing, window.y0 = a[1] - 0.5 * spacing;
  window.size = std::max(b[0] - a[0], b[1] - a[1]) + spacing;
  return window;
}

}  // namespace frostwall::report
