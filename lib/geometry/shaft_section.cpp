#include "geometry/shaft_section.hpp"

#include "geometry/voronoi_volumes.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <cmath>
#include <map>
#include <numbers>

#include "sph/symmetry_group.hpp"

namespace frostwall::geometry {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using sph::Vec;

Point point(const Vec<2>& p) { return {p[0], p[1]}; }

// The wedge side rays as CGAL points on them (origin O).
struct WedgeSides {
  Point O{0, 0}, A, B;
  explicit WedgeSides(const Wedge& w)
      : A(std::cos(w.start_angle), std::sin(w.start_angle)),
        B(std::cos(w.start_angle + w.angle), std::sin(w.start_angle + w.angle)) {}
};

}  // namespace

bool inside_wedge(const Wedge& wedge, const Vec<2>& p) {
  if (wedge.mirror_count == 0) return true;
  const WedgeSides s(wedge);
  const Point q = point(p);
  const bool left_of_OA = CGAL::orientation(s.O, s.A, q) == CGAL::LEFT_TURN;
  if (wedge.mirror_count == 1) return left_of_OA;  // a half plane
  return left_of_OA && CGAL::orientation(s.O, s.B, q) == CGAL::RIGHT_TURN;
}

ShaftScene build_shaft_section(const project::ShaftSection& section, const project::Domain& domain,
                               const Wedge& wedge, double spacing, double h) {
  ShaftScene scene;
  scene.wedge = wedge;
  scene.pipes = pipe_positions(section.layout);
  scene.far_field_radius = section.outer_radius;
  scene.pipe_radius = 0.5 * section.pipe.diameter;
  const double dx = spacing, R = section.outer_radius, a = scene.pipe_radius;
  const int layers = static_cast<int>(std::ceil(2.0 * h / dx - 1e-9));
  const bool disc = section.pipe.model == project::PipeModel::disc;

  scene.pipe_boundary = 0;
  scene.boundaries.push_back({"pipes", section.pipe.temperature});
  if (domain.far_field_temperature) {
    scene.far_field_boundary = 1;
    scene.boundaries.push_back({"far_field", project::TemperatureSchedule::fixed(*domain.far_field_temperature)});
  }

  std::vector<K::Circle_2> pipe_keep_out;  // no lattice particle inside these
  const double keep_out = disc ? a + 0.5 * dx : 0.5 * dx;
  for (const auto& p : scene.pipes) pipe_keep_out.emplace_back(Point(p.x, p.y), keep_out * keep_out);
  const K::Circle_2 far_field(Point(0, 0), R * R);
  const K::Circle_2 outermost(Point(0, 0), (R + layers * dx) * (R + layers * dx));

  auto& P = scene.particles;
  P.spacing = dx;
  const double volume = dx * dx;

  // The lattice, aligned with the wedge's second side.
  const double theta = wedge.mirror_count == 0 ? 0.0 : wedge.start_angle + wedge.angle;
  const Vec<2> e1(std::cos(theta), std::sin(theta)), e2(-std::sin(theta), std::cos(theta));
  const long n = static_cast<long>(std::ceil((R + layers * dx) / dx)) + 1;
  for (long i = -n; i <= n; ++i)
    for (long j = -n; j <= n; ++j) {
      const Vec<2> x = (i + 0.5) * dx * e1 + (j + 0.5) * dx * e2;
      if (!inside_wedge(wedge, x)) continue;
      const Point q = point(x);
      if (outermost.bounded_side(q) != CGAL::ON_BOUNDED_SIDE) continue;
      if (far_field.bounded_side(q) != CGAL::ON_BOUNDED_SIDE) {
        if (scene.far_field_boundary >= 0) P.add(x, volume, scene.far_field_boundary, x * (2.0 * R / x.norm() - 1.0));
        continue;
      }
      bool in_pipe = false;
      for (const auto& c : pipe_keep_out) in_pipe = in_pipe || c.bounded_side(q) != CGAL::ON_UNBOUNDED_SIDE;
      if (!in_pipe) P.add(x, volume, -1);
    }

  // Pipes: rings of fixed particles following the wall, symmetric about the
  // radial line through the pipe centre (a mirror line when the pipe sits on
  // a wedge side), or the single centre particle of the point model.
  for (const auto& p : scene.pipes) {
    const Vec<2> c(p.x, p.y);
    const double radial = std::atan2(p.y, p.x);
    auto keep = [&](const Vec<2>& x) { return inside_wedge(wedge, x); };
    if (!disc) {
      // On a wedge side the centre is its own mirror image and stays.
      const bool on_side = wedge.mirror_count > 0 && !keep(c) &&
                           (keep(c + 1e-6 * dx * Vec<2>(-std::sin(radial), std::cos(radial))) ||
                            keep(c - 1e-6 * dx * Vec<2>(-std::sin(radial), std::cos(radial))));
      if (keep(c) || on_side) P.add(c, volume, scene.pipe_boundary);
      continue;
    }
    for (int l = 0; l < layers; ++l) {
      const double rho = a - l * dx;
      if (rho < 0.5 * dx) {
        if (keep(c)) P.add(c, volume, scene.pipe_boundary);
        break;
      }
      const long count = std::max<long>(2, 2 * std::lround(std::numbers::pi * rho / dx));
      for (long m = 0; m < count; ++m) {
        const double phi = radial + (m + 0.5) * 2.0 * std::numbers::pi / count;
        const Vec<2> x = c + rho * Vec<2>(std::cos(phi), std::sin(phi));
        // Reflected across the pipe wall: radius 2a - rho from the centre.
        const Vec<2> reflected = l == 0 ? sph::ParticleSet<2>::on_wall() : Vec<2>(c + (2.0 * a - rho) / rho * (x - c));
        if (keep(x)) P.add(x, 2.0 * std::numbers::pi * rho / count * dx, scene.pipe_boundary, reflected);
      }
    }
  }

  if (wedge.mirror_count > 0) {
    // Planes through the origin; normals perpendicular to each side.
    P.mirrors.push_back({Vec<2>::Zero(), Vec<2>(-std::sin(wedge.start_angle), std::cos(wedge.start_angle))});
    if (wedge.mirror_count > 1) P.mirrors.push_back({Vec<2>::Zero(), e2});
  }
  P.order_free_first();
  assign_voronoi_volumes(P, 2.0 * h);
  return scene;
}

void unfold_to_full_ring(ShaftScene& scene) {
  const auto& wedge = scene.particles;
  if (wedge.mirrors.empty()) return;
  const auto group = sph::symmetry_group(wedge.mirrors, scene.far_field_radius);
  sph::ParticleSet<2> ring;
  ring.spacing = wedge.spacing;
  // A particle on a plane (a point pipe's centre) maps onto itself: once.
  std::map<std::pair<long long, long long>, bool> seen;
  const double grid = 1e-6 * wedge.spacing;
  for (const auto& g : group)
    for (std::size_t i = 0; i < wedge.size(); ++i) {
      const sph::Vec<2> y = g(wedge.position[i]);
      if (!seen.emplace(std::make_pair(std::llround(y[0] / grid), std::llround(y[1] / grid)), true).second) continue;
      ring.add(y, wedge.volume[i], wedge.boundary[i], g(wedge.reflection[i]));
    }
  ring.order_free_first();
  scene.particles = std::move(ring);
  scene.wedge = Wedge{0, scene.wedge.start_angle, 2 * std::numbers::pi};
}

}  // namespace frostwall::geometry
