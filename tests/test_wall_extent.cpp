// Story: the wall's extent is read off the particle field along rays. The
// sampler is checked against exact answers (a linear field at points of
// lattice symmetry, a symmetric field next to a mirror plane behaving as in
// the interior) and against a brute-force sum with every image written out;
// the frozen stretch of a ray against an analytic band; and the whole chain
// (lattice in a wedge -> sampler -> ray fan -> thinnest section) against a
// frozen band of known, angle-dependent thickness.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>
#include <numbers>
#include <random>

#include "geometry/voronoi_volumes.hpp"
#include "post/field_sampler.hpp"
#include "post/wall_extent.hpp"
#include "sph/kernel.hpp"
#include "particles/particle_set.hpp"

using namespace frostwall;
using post::Vec2;

namespace {

constexpr double smoothing_ratio = 1.3;  // h / spacing, the project default

// Square lattice of n x m cells of size d on [0, n d] x [0, m d], all free.
particles::ParticleSet<2> lattice(int n, int m, double d) {
  particles::ParticleSet<2> P;
  P.spacing = d;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) P.add(Vec2((i + 0.5) * d, (j + 0.5) * d), d * d, -1);
  P.order_free_first();
  return P;
}

template <class F>
std::vector<double> field_at(const particles::ParticleSet<2>& P, F&& f) {
  std::vector<double> v;
  for (const auto& x : P.position) v.push_back(f(x));
  return v;
}

}  // namespace

TEST_CASE("Shepard sampler: linear field exact at lattice-symmetric points", "[freezing][wall]") {
  const int n = 40;
  const double d = 1.0 / n, h = smoothing_ratio * d;
  const auto P = lattice(n, n, d);
  const sph::WendlandC2<2> kernel;
  const post::FieldSampler sampler(P, kernel, h);
  auto linear = [](const Vec2& x) { return 2.0 + 3.0 * x[0] - 5.0 * x[1]; };
  const auto field = field_at(P, linear);

  SECTION("constant: exact everywhere, also at the lattice's edge") {
    const std::vector<double> ones(P.size(), 1.0);
    for (const Vec2& x : {Vec2(0.0, 0.0), Vec2(0.013, 0.5), Vec2(0.377, 0.911), Vec2(1.01, 1.02)})
      CHECK(std::abs(sampler.value(x, ones) - 1.0) < 1e-14);
  }
  SECTION("linear: exact where the neighbourhood is point-symmetric") {
    // Particles, cell corners (lattice holes) and bond midpoints of the interior.
    double worst = 0.0;
    for (int j = 12; j <= 28; ++j)
      for (int i = 12; i <= 28; ++i)
        for (const Vec2& offset : {Vec2(0.5, 0.5), Vec2(0.0, 0.0), Vec2(0.5, 0.0), Vec2(0.0, 0.5)}) {
          const Vec2 x = (Vec2(i, j) + offset) * d;
          worst = std::max(worst, std::abs(sampler.value(x, field) - linear(x)));
        }
    CHECK(worst < 1e-12);
  }
  SECTION("linear, generic points: the lattice first moment's error is far below a spacing") {
    // Shepard interpolation is not first-order consistent off the symmetric
    // points: error = grad f . sum w_j (x_j - x), a lattice sum that is
    // periodic in x. Bound it relative to |grad f| d.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.3, 0.7);
    const double grad = std::hypot(3.0, 5.0);
    double worst = 0.0;
    for (int k = 0; k < 500; ++k) {
      const Vec2 x(u(rng), u(rng));
      worst = std::max(worst, std::abs(sampler.value(x, field) - linear(x)) / (grad * d));
    }
    fmt::print("\nShepard sampler, linear field at generic lattice points: error {:.2e} |grad f| spacing\n", worst);
    CHECK(worst < 1e-2);
  }
}

TEST_CASE("Shepard sampler near a mirror plane: a symmetric field as in the interior", "[freezing][wall]") {
  const sph::WendlandC2<2> kernel;
  // Error of y^2 sampled at height s*d above the plane y = 0 (lattice rows
  // half a spacing off it, so the images continue the lattice), against the
  // same field about an interior row-gap line y0 of an unmirrored lattice.
  auto errors = [&](int n) {
    const double d = 1.0 / n, h = smoothing_ratio * d;
    auto half = lattice(n, n / 2, d);
    half.mirrors = {{Vec2(0, 0), Vec2(0, 1)}};
    const auto full = lattice(n, n, d);
    const post::FieldSampler near_plane(half, kernel, h), interior(full, kernel, h);
    const double y0 = (n / 2) * d;
    const auto T_half = field_at(half, [](const Vec2& x) { return x[1] * x[1]; });
    const auto T_full = field_at(full, [&](const Vec2& x) { return (x[1] - y0) * (x[1] - y0); });
    // A field symmetric about the plane and linear along it: exact.
    const auto f_half = field_at(half, [](const Vec2& x) { return 1.0 + 3.0 * x[0]; });
    std::vector<double> e_plane, e_interior;
    double worst_linear = 0.0;
    for (double s : {0.0, 0.1, 0.25, 0.5, 0.8, 1.3, 2.7}) {
      for (double column : {n / 2.0, n / 2.0 + 0.5, n / 2.0 + 0.37}) {
        const Vec2 x(column * d, s * d);
        e_plane.push_back((near_plane.value(x, T_half) - x[1] * x[1]) / (d * d));
        e_interior.push_back((interior.value(x + Vec2(0, y0), T_full) - x[1] * x[1]) / (d * d));
        if (column != n / 2.0 + 0.37)
          worst_linear = std::max(worst_linear, std::abs(near_plane.value(x, f_half) - (1.0 + 3.0 * x[0])));
      }
    }
    CHECK(worst_linear < 1e-12);
    return std::pair(e_plane, e_interior);
  };
  const auto [coarse, coarse_interior] = errors(40);
  const auto [fine, fine_interior] = errors(80);
  for (std::size_t k = 0; k < coarse.size(); ++k) {
    // With the images the plane is invisible to the sampler.
    CHECK(std::abs(coarse[k] - coarse_interior[k]) < 1e-9);
    // O(d^2): the error in units of d^2 is the same on the finer lattice.
    CHECK(std::abs(coarse[k] - fine[k]) < 1e-8);
    CHECK(std::abs(coarse[k]) < 1.0);  // the kernel's variance across the plane, ~0.5 d^2 at h = 1.3 d
  }
  fmt::print("Shepard sampler, y^2 at a mirror plane: error up to {:.3f} spacing^2\n",
             std::abs(*std::max_element(coarse.begin(), coarse.end(),
                                        [](double a, double b) { return std::abs(a) < std::abs(b); })));
}

TEST_CASE("Field sampler and point probe agree with a brute-force sum over all images", "[freezing][wall]") {
  // A 20 x 20 square insulated on all four sides: images across each side
  // and across each corner (both reflections), written out by hand.
  const int n = 20;
  const double d = 1.0 / n, h = smoothing_ratio * d;
  auto P = lattice(n, n, d);
  P.mirrors = {{Vec2(0, 0), Vec2(1, 0)}, {Vec2(1, 0), Vec2(1, 0)}, {Vec2(0, 0), Vec2(0, 1)}, {Vec2(0, 1), Vec2(0, 1)}};
  const sph::CubicSpline<2> kernel;  // the other kernel than above
  const post::FieldSampler sampler(P, kernel, h);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> field(P.size());
  for (auto& v : field) v = u(rng);
  for (std::size_t i = 0; i < P.size(); ++i) P.volume[i] *= 0.5 + u(rng);  // uneven volumes (Voronoi cells)
  const post::FieldSampler uneven(P, kernel, h);

  auto brute = [&](const Vec2& x) {
    double sum = 0.0, total = 0.0;
    for (std::size_t j = 0; j < P.size(); ++j) {
      const Vec2 p = P.position[j];
      for (double px : {p[0], -p[0], 2.0 - p[0]})
        for (double py : {p[1], -p[1], 2.0 - p[1]}) {
          const double r = (Vec2(px, py) - x).norm();
          const double w = kernel.value(r, h) * P.volume[j];
          sum += w * field[j];
          total += w;
        }
    }
    return total > 0.0 ? sum / total : std::numeric_limits<double>::quiet_NaN();
  };

  std::vector<Vec2> where;
  for (int k = 0; k < 300; ++k) where.emplace_back(u(rng), u(rng));
  for (const Vec2& corner : {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0.002, 0.999)}) where.push_back(corner);
  where.emplace_back(5.0, 5.0);  // nothing within reach
  const auto batch = uneven.sample(where, field);
  const post::PointProbe probe(uneven, where);
  const auto probed = probe(field);
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < where.size(); ++k) {
    const double expected = brute(where[k]);
    worst = std::max({worst, std::abs(batch[k] - expected), std::abs(probed[k] - expected)});
    double sum_w = 0.0;
    for (const auto& [j, w] : uneven.weights(where[k])) sum_w += w;
    CHECK(std::abs(sum_w - 1.0) < 1e-13);
  }
  CHECK(worst < 1e-12);
  CHECK(std::isnan(batch.back()));
  CHECK(std::isnan(probed.back()));
  CHECK(uneven.weights(where.back()).empty());
  CHECK_THROWS_AS(sampler.value(Vec2(0.5, 0.5), std::vector<double>(3)), std::invalid_argument);
  CHECK_THROWS_AS(probe(std::vector<double>(3)), std::invalid_argument);
}

namespace {
// Liquid fraction of a frozen band inner < r < outer, ramping linearly to
// 1 over `ramp` across each edge (0.5 exactly on the edges).
double band(double r, double inner, double outer, double ramp) {
  return std::clamp(0.5 + std::max(inner - r, r - outer) / ramp, 0.0, 1.0);
}
}  // namespace

TEST_CASE("Frozen stretch of a ray: analytic band, linear interpolation of the crossings", "[freezing][wall]") {
  // Samples every 0.013 (not aligned with the band), so the nearest sample
  // would be off by up to 0.0065; interpolation between the two samples on
  // the ramp is exact.
  std::vector<double> r, f;
  for (double x = 3.0; x <= 7.0; x += 0.013) r.push_back(x);
  for (double x : r) f.push_back(band(x, 4.2, 5.7, 0.1));

  const auto s = post::frozen_stretch(r, f, 5.0);
  REQUIRE(s.frozen());
  CHECK(std::abs(*s.inner - 4.2) < 1e-12);
  CHECK(std::abs(*s.outer - 5.7) < 1e-12);
  CHECK(std::abs(s.thickness - 1.5) < 1e-12);

  SECTION("the ring outside the band: nothing frozen there") {
    for (double ring : {3.5, 6.5}) {
      const auto none = post::frozen_stretch(r, f, ring);
      CHECK_FALSE(none.inner.has_value());
      CHECK_FALSE(none.outer.has_value());
      CHECK(none.thickness == 0.0);
    }
    CHECK_FALSE(post::frozen_stretch(r, f, 8.0).frozen());  // beyond the sampled ray
  }
  SECTION("two bands: the one holding the ring") {
    std::vector<double> g;
    for (double x : r) g.push_back(std::min(band(x, 4.2, 5.7, 0.1), band(x, 6.2, 6.6, 0.1)));
    const auto second = post::frozen_stretch(r, g, 6.4);
    CHECK(std::abs(*second.inner - 6.2) < 1e-12);
    CHECK(std::abs(second.thickness - 0.4) < 1e-12);
    CHECK(std::abs(post::frozen_stretch(r, g, 5.0).thickness - 1.5) < 1e-12);
  }
  SECTION("a hole in the samples (pipe disc) is bridged; a ring radius on a sample or in the hole") {
    std::vector<double> holed = f;
    for (std::size_t i = 0; i < r.size(); ++i)
      if (std::abs(r[i] - 5.0) < 0.06) holed[i] = std::numeric_limits<double>::quiet_NaN();
    for (double ring : {5.0, r[150], 4.5}) {
      const auto bridged = post::frozen_stretch(r, holed, ring);
      CHECK(std::abs(*bridged.inner - 4.2) < 1e-12);
      CHECK(std::abs(*bridged.outer - 5.7) < 1e-12);
    }
  }
  SECTION("a band running to the end of the ray ends there") {
    std::vector<double> g;
    for (double x : r) g.push_back(band(x, 1.0, 5.7, 0.1));
    const auto open = post::frozen_stretch(r, g, 5.0);
    CHECK(*open.inner == r.front());
    CHECK(std::abs(*open.outer - 5.7) < 1e-12);
  }
  SECTION("bad input") {
    CHECK_THROWS_AS(post::frozen_stretch(r, std::vector<double>(3), 5.0), std::invalid_argument);
    CHECK_THROWS_AS(post::frozen_stretch({1.0, 0.5}, {0.0, 0.0}, 0.7), std::invalid_argument);
  }
}

TEST_CASE("Mean temperature over the frozen stretch: exact for T linear in r", "[freezing][wall]") {
  std::vector<double> r, f, T;
  for (double x = 3.0; x <= 7.0; x += 0.013) r.push_back(x);
  for (double x : r) {
    f.push_back(band(x, 4.2, 5.7, 0.1));
    T.push_back(-20.0 + 3.0 * x);
  }
  const auto s = post::frozen_stretch(r, f, 5.0);
  const auto mean = post::mean_over_frozen(r, f, T, s);
  REQUIRE(mean.has_value());
  CHECK(std::abs(*mean - (-20.0 + 3.0 * 4.95)) < 1e-12);  // T at the stretch's middle

  for (std::size_t i = 0; i < r.size(); ++i)
    if (std::abs(r[i] - 5.0) < 0.06) T[i] = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::abs(*post::mean_over_frozen(r, f, T, s) - (-20.0 + 3.0 * 4.95)) < 1e-12);
  CHECK_FALSE(post::mean_over_frozen(r, f, T, post::frozen_stretch(r, f, 6.5)).has_value());
}

TEST_CASE("Ray fan: rays one spacing apart at the ring, first on OA, last on OB", "[freezing][wall]") {
  const double angle = std::numbers::pi / 13, R = 5.0, d = 0.02;
  const int K = post::RayFan::rays_needed(angle, R, d);
  CHECK(angle * R / (K - 1) <= d);
  CHECK(angle * R / (K - 2) > d);
  const post::RayFan fan{0.4, angle, K, 0.0, 8.0, 0.01};
  CHECK(fan.ray_angle(0) == 0.4);
  CHECK(std::abs(fan.ray_angle(K - 1) - (0.4 + angle)) < 1e-15);
  const auto radii = fan.radii();
  CHECK(radii.front() == 0.0);
  CHECK(std::abs(radii.back() - 8.0) < 1e-12);
  CHECK(fan.points().size() == radii.size() * K);
}

namespace {

// A wedge from start_angle of `angle`: lattice aligned with OB, rows half a
// spacing off it (as the shaft builder lays it), free particles to r_out,
// both sides mirror planes. Built directly, without the shaft builder.
particles::ParticleSet<2> wedge_lattice(double start_angle, double angle, double r_out, double d) {
  particles::ParticleSet<2> P;
  P.spacing = d;
  const double theta = start_angle + angle;
  const Vec2 e1(std::cos(theta), std::sin(theta)), e2(-std::sin(theta), std::cos(theta));
  const Vec2 nA(-std::sin(start_angle), std::cos(start_angle));
  const long n = static_cast<long>(std::ceil(r_out / d)) + 1;
  for (long i = -n; i <= n; ++i)
    for (long j = -n; j <= n; ++j) {
      const Vec2 x = (i + 0.5) * d * e1 + (j + 0.5) * d * e2;
      if (x.norm() < r_out && x.dot(nA) > 0.0 && x.dot(e2) < 0.0) P.add(x, d * d, -1);
    }
  P.mirrors = {{Vec2::Zero(), nA}, {Vec2::Zero(), e2}};
  P.order_free_first();
  return P;
}

double polar_in_wedge(const Vec2& x, double start_angle) {
  double a = std::atan2(x[1], x[0]) - start_angle;
  while (a < -std::numbers::pi) a += 2 * std::numbers::pi;
  while (a >= std::numbers::pi) a -= 2 * std::numbers::pi;
  return a;
}

}  // namespace

TEST_CASE("Wall extents on a wedge lattice: thinnest section of an analytic frozen band", "[freezing][wall]") {
  // A frozen band around the ring r = R of half width w(theta), mirror
  // symmetric about both sides (w' = 0 there). Single ring: thinnest on OB.
  // Double ring or measured pipes: thinnest inside the wedge, missed by OA
  // and OB, found by the fan. Errors are largest on OA, where the lattice
  // (aligned with OB) meets its rotated images; Voronoi volumes (what the
  // shaft builder assigns) take out part of that seam's density error.
  const double start = 0.3, alpha = std::numbers::pi / 8, R = 5.0, d = 0.05, h = smoothing_ratio * d;
  const sph::WendlandC2<2> kernel;
  const int K = post::RayFan::rays_needed(alpha, R, d);
  REQUIRE(K % 2 == 1);  // a ray on the wedge's midline
  const post::RayFan fan{start, alpha, K, 0.0, 6.5, 0.5 * d};

  struct Case {
    const char* name;
    double w_sides, w_min;
    bool thinnest_inside;  // at theta = alpha / 2 instead of on OB
    double ramp;           // width of the liquid fraction's 0 -> 1 ramp
  };
  for (const bool voronoi : {false, true}) {
    auto P = wedge_lattice(start, alpha, 7.0, d);
    if (voronoi) geometry::assign_voronoi_volumes(P, 2 * h);
    const post::FieldSampler sampler(P, kernel, h);
    const post::WallGauge gauge(sampler, fan, {R});
    for (const Case& c :
         {Case{"single ring, smooth front", 0.6, 0.35, false, 0.3},
          Case{"single ring, sharp front", 0.6, 0.35, false, d}, Case{"double ring, smooth front", 0.7, 0.3, true, 0.3},
          Case{"double ring, sharp front", 0.7, 0.3, true, d}}) {
      auto w = [&](double theta) {
        const double shape = c.thinnest_inside ? std::cos(2 * std::numbers::pi * theta / alpha)
                                               : std::cos(std::numbers::pi * theta / alpha);
        return c.w_min + (c.w_sides - c.w_min) * (1.0 + shape) / 2.0;
      };
      const auto f = field_at(P, [&](const Vec2& x) {
        const double t = polar_in_wedge(x, start);
        return band(x.norm(), R - w(t), R + w(t), c.ramp);
      });
      const auto T = field_at(P, [](const Vec2& x) { return -12.0 + 2.0 * x.norm(); });
      const auto reading = gauge.measure(f, T);
      const auto& ex = reading.extents;
      REQUIRE(ex.rays.size() == static_cast<std::size_t>(K));
      double worst = 0.0, worst_inside = 0.0;  // all rays; rays more than a spacing off OA
      for (int k = 0; k < K; ++k) {
        const double t = fan.ray_angle(k) - start;
        REQUIRE(ex.rays[k].frozen());
        const double e = std::max(std::abs(*ex.rays[k].inner - (R - w(t))), std::abs(*ex.rays[k].outer - (R + w(t))));
        worst = std::max(worst, e);
        if (k > 1) worst_inside = std::max(worst_inside, e);
      }
      fmt::print("{}, {} volumes: min thickness {:.4f} (analytic {:.4f}) on ray {} of {}; "
                 "worst edge error {:.3f} spacing ({:.3f} off OA)\n",
                 c.name, voronoi ? "Voronoi" : "lattice", ex.min_thickness, 2 * c.w_min, ex.thinnest_ray, K, worst / d,
                 worst_inside / d);
      CHECK(worst < 0.3 * d);
      CHECK(worst_inside < 0.1 * d);
      CHECK(std::abs(ex.min_thickness - 2 * c.w_min) < 0.3 * d);
      CHECK(ex.thinnest_ray == (c.thinnest_inside ? (K - 1) / 2 : K - 1));
      // OA and OB alone would report the sides' thickness.
      if (c.thinnest_inside) CHECK(std::min(ex.OA().thickness, ex.OB().thickness) > 2 * c.w_min + 0.5);
      // Mean T over OB's stretch: T linear in r, so T at the stretch's middle R.
      REQUIRE(reading.mean_temperature_OB.has_value());
      CHECK(std::abs(*reading.mean_temperature_OB - (-12.0 + 2.0 * R)) < 2.0 * 0.3 * d);
    }

    // Before closure: columns around the pipes that do not reach OB yet
    // (w < 0 near OB), so OB is not frozen at the ring.
    auto w = [&](double theta) { return 0.45 - 0.7 * (1.0 - std::cos(std::numbers::pi * theta / alpha)) / 2.0; };
    const auto f = field_at(P, [&](const Vec2& x) {
      const double t = polar_in_wedge(x, start);
      return band(x.norm(), R - w(t), R + w(t), 0.3);
    });
    const auto reading = gauge.measure(f, std::vector<double>(P.size(), -5.0));
    CHECK(reading.extents.OA().frozen());
    CHECK(std::abs(reading.extents.OA().thickness - 0.9) < 0.3 * d);
    CHECK_FALSE(reading.extents.OB().inner.has_value());
    CHECK_FALSE(reading.extents.OB().outer.has_value());
    CHECK(reading.extents.OB().thickness == 0.0);
    CHECK(reading.extents.min_thickness == 0.0);
    CHECK_FALSE(reading.mean_temperature_OB.has_value());
  }
}

// Two rings (4.2 m and 5 m): the stretch is the longest frozen stretch that
// contains a ring radius. The inner ring's stretch alone while the two are
// apart (even when the outer one is thicker: the longest wins); one stretch
// over both once they merge; none when neither ring radius is frozen.
TEST_CASE("frozen_stretch: the longest stretch containing a ring of a double ring", "[freezing][wall]") {
  // Samples every 0.01 m; the frozen stretches end halfway between two
  // samples, where the piecewise-linear interpolant crosses 0.5.
  std::vector<double> r;
  for (int k = 0; k <= 300; ++k) r.push_back(3.0 + 0.01 * k);
  auto field = [&](auto frozen) {
    std::vector<double> f(r.size());
    for (std::size_t i = 0; i < r.size(); ++i) f[i] = frozen(r[i]) ? 0.0 : 1.0;
    return f;
  };
  const std::vector<double> rings = {4.2, 5.0};
  // Inner column 4.0-4.4 only: the outer ring radius is not frozen.
  const auto inner = post::frozen_stretch(r, field([](double x) { return x > 4.005 && x < 4.395; }), rings);
  REQUIRE(inner.frozen());
  CHECK(*inner.inner == Approx(4.005).margin(1e-9));
  CHECK(*inner.outer == Approx(4.395).margin(1e-9));
  CHECK(inner.thickness == Approx(0.39).margin(1e-9));
  // The outer ring's single-ring measure would call this ray unfrozen.
  CHECK_FALSE(post::frozen_stretch(r, field([](double x) { return x > 4.005 && x < 4.395; }), 5.0).frozen());
  // Both frozen, apart: the longer one (outer, 4.6-5.4).
  const auto apart = post::frozen_stretch(
      r, field([](double x) { return (x > 4.005 && x < 4.395) || (x > 4.605 && x < 5.395); }), rings);
  CHECK(apart.thickness == Approx(0.79).margin(1e-9));
  CHECK(*apart.inner == Approx(4.605).margin(1e-9));
  // Merged: one stretch 4.0-5.4 over both rings.
  const auto merged = post::frozen_stretch(r, field([](double x) { return x > 4.005 && x < 5.395; }), rings);
  CHECK(merged.thickness == Approx(1.39).margin(1e-9));
  // Frozen only between the rings, touching neither radius: nothing.
  CHECK_FALSE(post::frozen_stretch(r, field([](double x) { return x > 4.405 && x < 4.795; }), rings).frozen());
}
