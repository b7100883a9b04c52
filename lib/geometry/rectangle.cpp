#include "geometry/rectangle.hpp"

#include <cmath>
#include <fmt/core.h>

namespace frostwall::geometry {

namespace {

bool is_fixed(const project::SideCondition& c) { return std::holds_alternative<project::FixedTemperature>(c); }

// Particle rows along one axis of length L between a low and a high side.
struct AxisRows {
  double spacing = 0.0;
  std::vector<double> free;             // coordinates of free rows
  std::vector<double> below, above;     // fixed layers beyond each side (empty if mirror)
};

AxisRows axis_rows(double L, bool fixed_lo, bool fixed_hi, double s, int layers) {
  AxisRows a;
  // Fixed faces sit on a row, mirror planes halfway between rows.
  const double half_rows = (fixed_lo != fixed_hi) ? 0.5 : 0.0;
  const long m = std::max<long>(fixed_lo && fixed_hi ? 2 : 1, std::lround(L / s - half_rows));
  a.spacing = L / (static_cast<double>(m) + half_rows);
  const double d = a.spacing;
  // Free rows: k d (fixed low face) or (k + 1/2) d (mirror low side), k = 0..
  const double x0 = fixed_lo ? d : 0.5 * d;
  const long n_free = fixed_lo && fixed_hi ? m - 1 : m;
  for (long k = 0; k < n_free; ++k) a.free.push_back(x0 + k * d);
  if (fixed_lo)
    for (int l = 0; l < layers; ++l) a.below.push_back(a.free.front() - (l + 1) * d);
  if (fixed_hi)
    for (int l = 0; l < layers; ++l) a.above.push_back(a.free.back() + (l + 1) * d);
  return a;
}

}  // namespace

RectangleScene build_rectangle(const project::Rectangle& rect, double spacing, double h) {
  RectangleScene scene;
  const int layers = static_cast<int>(std::ceil(2.0 * h / spacing - 1e-9));
  const AxisRows X = axis_rows(rect.width, is_fixed(rect.left), is_fixed(rect.right), spacing, layers);
  const AxisRows Y = axis_rows(rect.height, is_fixed(rect.bottom), is_fixed(rect.top), spacing, layers);
  scene.spacing = {X.spacing, Y.spacing};
  for (int d = 0; d < 2; ++d)
    if (std::abs(scene.spacing[d] - spacing) > 1e-9 * spacing)
      scene.notes.push_back(fmt::format("numerics.spacing: {:.6g} m along {} to fit the rectangle (asked {:.6g} m)",
                                        scene.spacing[d], d == 0 ? "x" : "y", spacing));

  // Boundary ids in the order left, right, bottom, top (fixed sides only);
  // a corner particle beyond two fixed sides belongs to the first.
  const std::array<std::pair<const char*, const project::SideCondition*>, 4> sides{
      {{"left", &rect.left}, {"right", &rect.right}, {"bottom", &rect.bottom}, {"top", &rect.top}}};
  std::array<int, 4> id{-1, -1, -1, -1};
  for (int s = 0; s < 4; ++s)
    if (is_fixed(*sides[s].second)) {
      id[s] = static_cast<int>(scene.boundaries.size());
      scene.boundaries.push_back({sides[s].first, std::get<project::FixedTemperature>(*sides[s].second).temperature});
    }

  auto with = [](std::vector<double> a, const std::vector<double>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<double> xs = with(with(X.free, X.below), X.above);
  const std::vector<double> ys = with(with(Y.free, Y.below), Y.above);
  const double volume = X.spacing * Y.spacing;
  auto& P = scene.particles;
  P.spacing = std::min(X.spacing, Y.spacing);
  for (double y : ys)
    for (double x : xs) {
      const std::array<bool, 4> beyond{x < X.free.front() - 1e-12 * X.spacing, x > X.free.back() + 1e-12 * X.spacing,
                                       y < Y.free.front() - 1e-12 * Y.spacing, y > Y.free.back() + 1e-12 * Y.spacing};
      int b = -1, owner = -1, count = 0;
      for (int s = 3; s >= 0; --s)
        if (beyond[s]) {
          b = id[s];
          owner = s;
          ++count;
        }
      // The point this layer particle mirrors across its face (the face row
      // and corner particles beyond two faces hold the wall temperature).
      sph::Vec<2> reflected = sph::ParticleSet<2>::on_wall();
      const double wall[4] = {0.0, rect.width, 0.0, rect.height};
      if (count == 1 && std::abs((owner < 2 ? x : y) - wall[owner]) > 1e-9 * X.spacing)
        reflected = owner < 2 ? sph::Vec<2>(2 * wall[owner] - x, y) : sph::Vec<2>(x, 2 * wall[owner] - y);
      P.add(sph::Vec<2>(x, y), volume, b, reflected);
    }
  using V = sph::Vec<2>;
  if (!is_fixed(rect.left)) P.mirrors.push_back({V(0, 0), V(1, 0)});
  if (!is_fixed(rect.right)) P.mirrors.push_back({V(rect.width, 0), V(1, 0)});
  if (!is_fixed(rect.bottom)) P.mirrors.push_back({V(0, 0), V(0, 1)});
  if (!is_fixed(rect.top)) P.mirrors.push_back({V(0, rect.height), V(0, 1)});
  P.order_free_first();
  return scene;
}

std::optional<CooledFace> cooled_face(const project::Rectangle& rect, const RectangleScene& scene) {
  using V = sph::Vec<2>;
  const std::array<CooledFace, 4> faces{{{"left", V(0, 0), V(1, 0), scene.spacing[0]},
                                         {"right", V(rect.width, 0), V(-1, 0), scene.spacing[0]},
                                         {"bottom", V(0, 0), V(0, 1), scene.spacing[1]},
                                         {"top", V(0, rect.height), V(0, -1), scene.spacing[1]}}};
  const std::array<const project::SideCondition*, 4> conditions{&rect.left, &rect.right, &rect.bottom, &rect.top};
  std::optional<CooledFace> coldest;
  double coldest_T = 0.0;
  for (int s = 0; s < 4; ++s) {
    if (!is_fixed(*conditions[s])) continue;
    const double T = std::get<project::FixedTemperature>(*conditions[s]).temperature.at(0.0);
    if (!coldest || T < coldest_T) {
      coldest = faces[s];
      coldest_T = T;
    }
  }
  return coldest;
}

}  // namespace frostwall::geometry
