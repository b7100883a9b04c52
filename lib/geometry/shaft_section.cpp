#include "geometry/shaft_section.hpp"

#include "geometry/graded_placement.hpp"
#include "geometry/voronoi_volumes.hpp"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <map>
#include <numbers>

#include "particles/symmetry_group.hpp"
#include "pipes/pipe_exchange.hpp"

namespace frostwall::geometry {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using particles::Vec;

Point point(const Vec<2>& p) { return {p[0], p[1]}; }

// The wedge side rays as CGAL points on them (origin O).
struct WedgeSides {
  Point O{0, 0}, A, B;
  explicit WedgeSides(const Wedge& w)
      : A(std::cos(w.start_angle), std::sin(w.start_angle)),
        B(std::cos(w.start_angle + w.angle), std::sin(w.start_angle + w.angle)) {}
};

// Pipes: rings of fixed particles following the wall, symmetric about the
// radial line through the pipe centre (a mirror line when the pipe sits on
// a wedge side), or the single centre particle of the point model. `dx` is
// the spacing at the pipe; `volume` the point model's particle volume.
void add_pipe(particles::ParticleSet<2>& P, const ShaftScene& scene, const Wedge& wedge, const Pipe2& p, bool disc,
              double a, double dx, int layers, double volume) {
  const Vec<2> c(p.x, p.y);
  const double radial = std::atan2(p.y, p.x);
  auto keep = [&](const Vec<2>& x) { return inside_wedge(wedge, x); };
  if (!disc) {
    // On a wedge side the centre is its own mirror image and stays.
    const bool on_side = wedge.mirror_count > 0 && !keep(c) &&
                         (keep(c + 1e-6 * dx * Vec<2>(-std::sin(radial), std::cos(radial))) ||
                          keep(c - 1e-6 * dx * Vec<2>(-std::sin(radial), std::cos(radial))));
    if (keep(c) || on_side) P.add(c, volume, scene.pipe_boundary);
    return;
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
      const Vec<2> reflected = l == 0 ? particles::ParticleSet<2>::on_wall()
                                      : Vec<2>(c + (2.0 * a - rho) / rho * (x - c));
      if (keep(x)) P.add(x, 2.0 * std::numbers::pi * rho / count * dx, scene.pipe_boundary, reflected);
    }
  }
}

// What both builders share: pipes, radii, boundaries.
ShaftScene empty_scene(const project::ShaftSection& section, const project::Domain& domain, const Wedge& wedge) {
  ShaftScene scene;
  scene.wedge = wedge;
  scene.pipes = pipe_positions(section.layout);
  scene.far_field_radius = section.outer_radius;
  scene.pipe_radius = 0.5 * section.pipe.diameter;
  scene.pipe_boundary = 0;
  scene.boundaries.push_back({"pipes", section.pipe.temperature});
  if (domain.far_field_temperature) {
    scene.far_field_boundary = 1;
    scene.boundaries.push_back({"far_field", project::TemperatureSchedule::fixed(*domain.far_field_temperature)});
  }
  return scene;
}

void add_mirror_planes(particles::ParticleSet<2>& P, const Wedge& wedge) {
  if (wedge.mirror_count == 0) return;
  // Planes through the origin; normals perpendicular to each side.
  const double theta = wedge.start_angle + wedge.angle;
  P.mirrors.push_back({Vec<2>::Zero(), Vec<2>(-std::sin(wedge.start_angle), std::cos(wedge.start_angle))});
  if (wedge.mirror_count > 1) P.mirrors.push_back({Vec<2>::Zero(), Vec<2>(-std::sin(theta), std::cos(theta))});
}

// Distance from x to the wedge (0 inside), the wedge's sides cut at R.
double distance_to_wedge(const Wedge& wedge, double R, const Vec<2>& x) {
  if (wedge.mirror_count == 0 || inside_wedge(wedge, x)) return 0.0;
  auto to_side = [&](double angle) {
    const Vec<2> e(std::cos(angle), std::sin(angle));
    const double t = std::clamp(x.dot(e), 0.0, R);
    return (x - t * e).norm();
  };
  return std::min(to_side(wedge.start_angle), to_side(wedge.start_angle + wedge.angle));
}

}  // namespace

bool inside_wedge(const Wedge& wedge, const Vec<2>& p) {
  if (wedge.mirror_count == 0) return true;
  const WedgeSides s(wedge);
  const Point q = point(p);
  const bool left_of_OA = CGAL::orientation(s.O, s.A, q) == CGAL::LEFT_TURN;
  if (wedge.mirror_count == 1) return left_of_OA;  // a half plane
  return left_of_OA && CGAL::orientation(s.O, s.B, q) == CGAL::RIGHT_TURN;
}

ShaftScene build_shaft_section(const project::ShaftSection& section, const project::Domain& domain, const Wedge& wedge,
                               double spacing, double h) {
  ShaftScene scene = empty_scene(section, domain, wedge);
  const double dx = spacing, R = section.outer_radius, a = scene.pipe_radius;
  const int layers = static_cast<int>(std::ceil(2.0 * h / dx - 1e-9));
  const auto exchange = pipes::make_pipe_exchange(section.pipe.model);
  const bool disc = exchange->rings_on_wall();

  std::vector<K::Circle_2> pipe_keep_out;  // no lattice particle inside these
  const double keep_out = exchange->keep_out(a, dx);
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

  for (const auto& p : scene.pipes) add_pipe(P, scene, wedge, p, disc, a, dx, layers, volume);

  add_mirror_planes(P, wedge);
  P.order_free_first();
  assign_voronoi_volumes(P, 2.0 * h);
  return scene;
}

SizeField shaft_size_field(const project::ShaftSection& section, const Wedge& wedge, double finest,
                           const project::Grading& grading) {
  const double coarsest = grading.coarsening * finest, slope = grading.growth - 1.0;
  const double R = section.outer_radius, a = 0.5 * section.pipe.diameter;
  SizeField size(finest, coarsest);
  const auto pipes = pipe_positions(section.layout);
  double r_in = R, r_out = 0.0;
  for (const auto& p : pipes) {
    const Vec<2> c(p.x, p.y);
    r_in = std::min(r_in, c.norm());
    r_out = std::max(r_out, c.norm());
    // A pipe's own cone matters up to where it reaches the coarsest spacing.
    if (distance_to_wedge(wedge, R, c) < a + (coarsest - finest) / slope)
      size.near_circle(c, project::has_wall(section.pipe.model) ? a : 0.0, finest, slope);
  }
  const double w = grading.band_width.value_or(2.0);
  size.in_annulus(r_in - w, r_out + w, grading.band_coarsening * finest, slope);
  // Near the apex the wedge's 2M mirror copies put rings of images r * angle
  // apart round the axis: a particle there cannot be coarser than that.
  if (wedge.mirror_count > 1) size.add([](const Vec<2>& x) { return x.norm(); }, 0.0, std::min(slope, wedge.angle));
  return size;
}

ShaftScene build_graded_shaft_section(const project::ShaftSection& section, const project::Domain& domain,
                                      const Wedge& wedge, const SizeField& size, double smoothing_ratio) {
  ShaftScene scene = empty_scene(section, domain, wedge);
  const double R = section.outer_radius, a = scene.pipe_radius;
  const auto exchange = pipes::make_pipe_exchange(section.pipe.model);
  const bool disc = exchange->rings_on_wall();
  auto& P = scene.particles;
  P.spacing = size.finest();
  add_mirror_planes(P, wedge);

  // Pipe rings at the spacing of each pipe's wall, kept aside while the
  // free particles settle round them.
  particles::ParticleSet<2> rings;
  std::vector<double> ring_spacing;
  for (const auto& p : scene.pipes) {
    const Vec<2> c(p.x, p.y);
    const double s = size(c + Vec<2>(a, 0.0));
    const int layers = static_cast<int>(std::ceil(2.0 * smoothing_ratio - 1e-9));
    add_pipe(rings, scene, wedge, p, disc, a, s, layers, s * s);
    ring_spacing.resize(rings.size(), s);
  }

  PlacementRegion region;
  const double ends = std::max(8.0, std::ceil(wedge.angle * R / (0.5 * size.coarsest())));
  if (wedge.mirror_count > 0) region.outline.push_back(Vec<2>::Zero());
  for (long k = 0; k <= static_cast<long>(ends); ++k) {
    if (wedge.mirror_count == 0 && k == static_cast<long>(ends)) break;  // a closed circle
    const double phi = wedge.start_angle + wedge.angle * k / ends;
    region.outline.push_back(R * Vec<2>(std::cos(phi), std::sin(phi)));
  }
  region.inside = [&](const Vec<2>& x) {
    if (!inside_wedge(wedge, x) || x.norm() >= R) return false;
    const double keep_out = exchange->keep_out(a, 0.6 * size(x));
    for (const auto& p : scene.pipes)
      if ((x - Vec<2>(p.x, p.y)).norm() < keep_out) return false;
    return true;
  };
  region.mirrors = P.mirrors;
  region.fixed = rings.position;
  region.walls.push_back({Vec<2>::Zero(), Vec<2>::UnitX(), R});
  PlacementReport report;
  const std::vector<Vec<2>> free = place_graded(region, size, 40, &report);

  // Free particles first (volumes follow), then the rings, then the far
  // field: each free particle within reach of the circle reflected across it.
  for (const auto& x : free) P.add(x, 0.0, -1);
  for (std::size_t k = 0; k < rings.size(); ++k)
    P.add(rings.position[k], rings.volume[k], rings.boundary[k], rings.reflection[k]);
  std::vector<std::size_t> far_source;
  if (scene.far_field_boundary >= 0)
    for (std::size_t i = 0; i < free.size(); ++i)
      if (R - free[i].norm() < 2.2 * smoothing_ratio * size(free[i])) {
        P.add(region.walls[0].reflect(free[i]), 0.0, scene.far_field_boundary, free[i]);
        far_source.push_back(i);
      }
  P.order_free_first();  // already in order: keeps the indices above
  assign_voronoi_volumes(P, 2.0 * smoothing_ratio * size.coarsest());

  const double scale = assign_free_spacing(P, size);
  for (std::size_t k = 0; k < rings.size(); ++k) P.local_spacing[P.n_free + k] = ring_spacing[k];
  for (std::size_t k = 0; k < far_source.size(); ++k) {
    const std::size_t j = P.n_free + rings.size() + k, i = far_source[k];
    const double r = P.position[i].norm();
    P.volume[j] = P.volume[i] * (2.0 * R - r) / r;  // the radial reflection stretches arcs by (2R - r)/r
    P.local_spacing[j] = P.local_spacing[i];
  }
  P.spacing = *std::min_element(P.local_spacing.begin(), P.local_spacing.end());
  scene.notes.push_back(fmt::format(
      "placement: graded, {} free particles (CVT, {} Lloyd iterations, last move {:.3f} spacings), spacing {:.4g} to "
      "{:.4g} m, scale {:.3f}",
      P.n_free, report.iterations, report.last_move, P.spacing, P.coarsest_spacing(), scale));
  return scene;
}

void unfold_to_full_ring(ShaftScene& scene) {
  const auto& wedge = scene.particles;
  if (wedge.mirrors.empty()) return;
  const auto group = particles::symmetry_group(wedge.mirrors, scene.far_field_radius);
  particles::ParticleSet<2> ring;
  ring.spacing = wedge.spacing;
  const bool graded = wedge.graded();
  // A particle on a plane (a point pipe's centre) maps onto itself: once.
  std::map<std::pair<long long, long long>, bool> seen;
  const double grid = 1e-6 * wedge.spacing;
  for (const auto& g : group)
    for (std::size_t i = 0; i < wedge.size(); ++i) {
      const particles::Vec<2> y = g(wedge.position[i]);
      if (!seen.emplace(std::make_pair(std::llround(y[0] / grid), std::llround(y[1] / grid)), true).second) continue;
      ring.add(y, wedge.volume[i], wedge.boundary[i], g(wedge.reflection[i]));
      if (graded) ring.local_spacing.push_back(wedge.local_spacing[i]);
    }
  ring.order_free_first();
  scene.particles = std::move(ring);
  scene.wedge = Wedge{0, scene.wedge.start_angle, 2 * std::numbers::pi};
}

}  // namespace frostwall::geometry
