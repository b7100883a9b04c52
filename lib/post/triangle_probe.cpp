#include "post/triangle_probe.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "geometry/triangulation.hpp"

namespace frostwall::post {

using Vec2 = particles::Vec<2>;

namespace {

// The barycentric coordinates of x in the triangle (a, b, c), or nullopt
// when x lies outside it (by more than a rounding error).
std::optional<std::array<double, 3>> barycentric(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& x) {
  const Vec2 u = b - a, v = c - a, w = x - a;
  const double det = u[0] * v[1] - u[1] * v[0];
  if (std::abs(det) <= 0.0) return std::nullopt;
  const double lb = (w[0] * v[1] - w[1] * v[0]) / det, lc = (u[0] * w[1] - u[1] * w[0]) / det;
  const double la = 1.0 - lb - lc, tol = 1e-12;
  if (la < -tol || lb < -tol || lc < -tol) return std::nullopt;
  return std::array{std::max(la, 0.0), std::max(lb, 0.0), std::max(lc, 0.0)};
}

// The triangle round x in the Delaunay triangulation of its `count` nearest
// points: the global triangulation's triangle that holds x has an empty
// circumcircle, so it is one of the local triangulation's too whenever its
// corners are among those points.
std::optional<std::vector<TriangleProbe::Corner>> local_triangle(const std::vector<Vec2>& points,
                                                                 const std::vector<std::uint32_t>& source,
                                                                 const std::vector<std::size_t>& by_distance,
                                                                 std::size_t count, const Vec2& x) {
  count = std::min(count, by_distance.size());
  std::vector<Vec2> near(count);
  for (std::size_t k = 0; k < count; ++k) near[k] = points[by_distance[k]];
  for (const auto& f : geometry::delaunay_faces(near)) {
    const auto l = barycentric(near[f[0]], near[f[1]], near[f[2]], x);
    if (!l) continue;
    std::vector<TriangleProbe::Corner> corners;
    for (int c = 0; c < 3; ++c) {
      const std::uint32_t index = source[by_distance[f[c]]];
      auto same = std::find_if(corners.begin(), corners.end(), [&](const auto& e) { return e.index == index; });
      if (same != corners.end()) same->weight += (*l)[c];
      else corners.push_back({index, (*l)[c]});
    }
    return corners;
  }
  return std::nullopt;
}

}  // namespace

TriangleProbe::TriangleProbe(const std::vector<Vec2>& points, const std::vector<std::uint32_t>& source,
                             const std::vector<Vec2>& where) {
  for (const Vec2& x : where) {
    std::vector<double> d2(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) d2[k] = (points[k] - x).squaredNorm();
    std::vector<std::size_t> order(points.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    const std::size_t keep = std::min<std::size_t>(order.size(), 256);
    std::partial_sort(order.begin(), order.begin() + static_cast<long>(keep), order.end(),
                      [&](std::size_t a, std::size_t b) { return d2[a] < d2[b]; });
    order.resize(keep);
    std::optional<std::vector<Corner>> found;
    for (std::size_t count : {32, 256})
      if ((found = local_triangle(points, source, order, count, x))) break;
    if (!found && !order.empty()) found = std::vector<Corner>{{source[order.front()], 1.0}};
    weights_.push_back(found.value_or(std::vector<Corner>{}));
  }
}

double TriangleProbe::at(std::size_t k, const std::vector<double>& field) const {
  if (weights_[k].empty()) return std::numeric_limits<double>::quiet_NaN();
  double v = 0.0;
  for (const auto& c : weights_[k]) v += c.weight * field[c.index];
  return v;
}

std::vector<double> TriangleProbe::operator()(const std::vector<double>& field) const {
  std::vector<double> out(size());
  for (std::size_t k = 0; k < size(); ++k) out[k] = at(k, field);
  return out;
}

}  // namespace frostwall::post
