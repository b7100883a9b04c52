#include "geometry/rectangle.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/graded_placement.hpp"
#include "geometry/voronoi_volumes.hpp"
#include <fmt/core.h>

namespace frostwall::geometry {

namespace {

bool is_fixed(const project::SideCondition& c) { return std::holds_alternative<project::FixedTemperature>(c); }

// How a side is laid: a fixed temperature (face on a row, fixed layers
// beyond), a mirror plane (halfway between rows), or open (an adiabatic
// face with a head: halfway between rows, fixed layers beyond that copy
// their reflections).
enum class Side { fixed, mirror, open };

// Particle rows along one axis of length L between a low and a high side.
struct AxisRows {
  double spacing = 0.0;
  std::vector<double> free;          // coordinates of free rows
  std::vector<double> below, above;  // fixed layers beyond each side (empty if mirror)
};

AxisRows axis_rows(double L, Side lo, Side hi, double s, int layers) {
  const bool fixed_lo = lo == Side::fixed, fixed_hi = hi == Side::fixed;
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
  if (lo != Side::mirror)
    for (int l = 0; l < layers; ++l) a.below.push_back(a.free.front() - (l + 1) * d);
  if (hi != Side::mirror)
    for (int l = 0; l < layers; ++l) a.above.push_back(a.free.back() + (l + 1) * d);
  return a;
}

Side side_kind(const project::SideCondition& condition, const std::optional<double>& head) {
  if (is_fixed(condition)) return Side::fixed;
  return head ? Side::open : Side::mirror;
}

}  // namespace

RectangleScene build_rectangle(const project::Rectangle& rect, double spacing, double h) {
  RectangleScene scene;
  const int layers = static_cast<int>(std::ceil(2.0 * h / spacing - 1e-9));
  // The sides in the order left, right, bottom, top (Rectangle::heads').
  const std::array<std::pair<const char*, const project::SideCondition*>, 4> sides{
      {{"left", &rect.left}, {"right", &rect.right}, {"bottom", &rect.bottom}, {"top", &rect.top}}};
  std::array<Side, 4> kind;
  for (int s = 0; s < 4; ++s) kind[s] = side_kind(*sides[s].second, rect.heads[s]);
  const AxisRows X = axis_rows(rect.width, kind[0], kind[1], spacing, layers);
  const AxisRows Y = axis_rows(rect.height, kind[2], kind[3], spacing, layers);
  scene.spacing = {X.spacing, Y.spacing};
  for (int d = 0; d < 2; ++d)
    if (std::abs(scene.spacing[d] - spacing) > 1e-9 * spacing)
      scene.notes.push_back(fmt::format("numerics.spacing: {:.6g} m along {} to fit the rectangle (asked {:.6g} m)",
                                        scene.spacing[d], d == 0 ? "x" : "y", spacing));

  // Boundary ids in the sides' order (fixed and open sides); a corner
  // particle beyond two such sides belongs to the first.
  std::array<int, 4> id{-1, -1, -1, -1};
  for (int s = 0; s < 4; ++s) {
    if (kind[s] == Side::mirror) continue;
    id[s] = static_cast<int>(scene.boundaries.size());
    if (kind[s] == Side::fixed)
      scene.boundaries.push_back({sides[s].first, std::get<project::FixedTemperature>(*sides[s].second).temperature});
    else scene.boundaries.push_back({sides[s].first, project::TemperatureSchedule::fixed(0.0), std::nullopt, true});
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
      const std::array<bool, 4> beyond{x<X.free.front() - 1e-12 * X.spacing, x> X.free.back() + 1e-12 * X.spacing,
                                       y<Y.free.front() - 1e-12 * Y.spacing, y> Y.free.back() + 1e-12 * Y.spacing};
      int b = -1, owner = -1, count = 0;
      for (int s = 3; s >= 0; --s)
        if (beyond[s]) {
          b = id[s];
          owner = s;
          ++count;
        }
      // The point this layer particle mirrors across its face (the face row
      // and corner particles beyond two faces hold the wall temperature).
      particles::Vec<2> reflected = particles::ParticleSet<2>::on_wall();
      const double wall[4] = {0.0, rect.width, 0.0, rect.height};
      if (count == 1 && std::abs((owner < 2 ? x : y) - wall[owner]) > 1e-9 * X.spacing)
        reflected = owner < 2 ? particles::Vec<2>(2 * wall[owner] - x, y) : particles::Vec<2>(x, 2 * wall[owner] - y);
      // An open side's corner particles reflect across both sides.
      if (count == 2 && kind[owner] == Side::open)
        reflected = particles::Vec<2>(beyond[0]   ? -x
                                      : beyond[1] ? 2 * rect.width - x
                                                  : x,
                                      beyond[2]   ? -y
                                      : beyond[3] ? 2 * rect.height - y
                                                  : y);
      P.add(particles::Vec<2>(x, y), volume, b, reflected);
    }
  using V = particles::Vec<2>;
  if (kind[0] == Side::mirror) P.mirrors.push_back({V(0, 0), V(1, 0)});
  if (kind[1] == Side::mirror) P.mirrors.push_back({V(rect.width, 0), V(1, 0)});
  if (kind[2] == Side::mirror) P.mirrors.push_back({V(0, 0), V(0, 1)});
  if (kind[3] == Side::mirror) P.mirrors.push_back({V(0, rect.height), V(0, 1)});
  P.order_free_first();
  return scene;
}

namespace {
// The coldest fixed side at t = 0 (index left, right, bottom, top), -1 if none.
int coldest_side(const project::Rectangle& rect) {
  const std::array<const project::SideCondition*, 4> conditions{&rect.left, &rect.right, &rect.bottom, &rect.top};
  int coldest = -1;
  double coldest_T = 0.0;
  for (int s = 0; s < 4; ++s) {
    if (!is_fixed(*conditions[s])) continue;
    const double T = std::get<project::FixedTemperature>(*conditions[s]).temperature.at(0.0);
    if (coldest < 0 || T < coldest_T) {
      coldest = s;
      coldest_T = T;
    }
  }
  return coldest;
}

// Side s as a line: a point on it and its inward normal.
std::pair<particles::Vec<2>, particles::Vec<2>> side_line(const project::Rectangle& rect, int s) {
  using V = particles::Vec<2>;
  switch (s) {
    case 0: return {V(0, 0), V(1, 0)};
    case 1: return {V(rect.width, 0), V(-1, 0)};
    case 2: return {V(0, 0), V(0, 1)};
    default: return {V(0, rect.height), V(0, -1)};
  }
}
}  // namespace

SizeField rectangle_size_field(const project::Rectangle& rect, double finest, const project::Grading& grading) {
  const double coarsest = std::min(grading.coarsening * finest, 0.5 * std::min(rect.width, rect.height));
  SizeField size(finest, std::max(finest, coarsest));
  const int s = coldest_side(rect);
  if (s < 0) return size;  // nothing cooled: as coarse as allowed
  const auto [point, normal] = side_line(rect, s);
  const double across = s < 2 ? rect.width : rect.height;
  const double slope = grading.growth - 1.0;
  size.near_line(point, normal, 0.0, finest, slope);
  size.near_line(point, normal, grading.band_width.value_or(across / 3.0), grading.band_coarsening * finest, slope);
  return size;
}

RectangleScene build_graded_rectangle(const project::Rectangle& rect, const SizeField& size, double smoothing_ratio) {
  RectangleScene scene;
  const std::array<const project::SideCondition*, 4> sides{&rect.left, &rect.right, &rect.bottom, &rect.top};
  const std::array<const char*, 4> names{"left", "right", "bottom", "top"};
  std::array<int, 4> id{-1, -1, -1, -1};
  for (int s = 0; s < 4; ++s)
    if (is_fixed(*sides[s])) {
      id[s] = static_cast<int>(scene.boundaries.size());
      scene.boundaries.push_back({names[s], std::get<project::FixedTemperature>(*sides[s]).temperature});
    }
  auto& P = scene.particles;
  using V = particles::Vec<2>;
  std::array<ReflectingWall, 4> wall;
  PlacementRegion region;
  region.outline = {V(0, 0), V(rect.width, 0), V(rect.width, rect.height), V(0, rect.height)};
  region.inside = [&](const V& x) { return x[0] > 0 && x[0] < rect.width && x[1] > 0 && x[1] < rect.height; };
  for (int s = 0; s < 4; ++s) {
    const auto [point, normal] = side_line(rect, s);
    wall[s] = {point, normal, 0.0};
    if (id[s] >= 0) region.walls.push_back(wall[s]);
    else P.mirrors.push_back({point, V(std::abs(normal[0]), std::abs(normal[1]))});
  }
  region.mirrors = P.mirrors;
  PlacementReport report;
  const std::vector<V> free = place_graded(region, size, 40, &report);

  for (const auto& x : free) P.add(x, 0.0, -1);
  // Reflections across the fixed sides, then across two (corners).
  std::vector<std::size_t> source;
  auto reach = [&](const V& x) { return 2.2 * smoothing_ratio * size(x); };
  for (int s = 0; s < 4; ++s) {
    if (id[s] < 0) continue;
    for (std::size_t i = 0; i < free.size(); ++i)
      if (wall[s].distance(free[i]) < reach(free[i])) {
        P.add(wall[s].reflect(free[i]), 0.0, id[s], free[i]);
        source.push_back(i);
      }
  }
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b) {
      if (id[a] < 0 || id[b] < 0 || (a < 2) == (b < 2)) continue;  // two fixed sides meeting at a corner
      for (std::size_t i = 0; i < free.size(); ++i)
        if (wall[a].distance(free[i]) < reach(free[i]) && wall[b].distance(free[i]) < reach(free[i])) {
          P.add(wall[b].reflect(wall[a].reflect(free[i])), 0.0, id[a]);
          source.push_back(i);
        }
    }
  P.order_free_first();  // already in order
  assign_voronoi_volumes(P, 2.0 * smoothing_ratio * size.coarsest());
  const double scale = assign_free_spacing(P, size);
  for (std::size_t k = 0; k < source.size(); ++k) {
    P.volume[P.n_free + k] = P.volume[source[k]];
    P.local_spacing[P.n_free + k] = P.local_spacing[source[k]];
  }
  P.spacing = *std::min_element(P.local_spacing.begin(), P.local_spacing.end());
  scene.spacing = {P.spacing, P.spacing};
  scene.notes.push_back(fmt::format(
      "placement: graded, {} free particles (CVT, {} Lloyd iterations, last move {:.3f} spacings), spacing {:.4g} to "
      "{:.4g} m, scale {:.3f}",
      P.n_free, report.iterations, report.last_move, P.spacing, P.coarsest_spacing(), scale));
  return scene;
}

std::optional<CooledFace> cooled_face(const project::Rectangle& rect, const RectangleScene& scene) {
  using V = particles::Vec<2>;
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
  if (coldest && scene.particles.graded()) coldest->lattice_rows = false;
  return coldest;
}

}  // namespace frostwall::geometry
