// Story: closure is the frozen ground cutting the unfrozen ground around the
// shaft axis off from the far field. The detector reduces that to one
// number, the bottleneck b of a per-particle field (liquid fraction, or the
// run's unclamped H / H_latent): touching when b <= 0.5, closed when
// b <= 0 (fully frozen). It is
// checked on hand-built lattices (positions only, no solver) with liquid
// fractions set by hand, so every expected b is an exact value of the field:
//  - full disc: a closed frozen ring (b = 0); the ring with a one-particle
//    gap (b = the gap's liquid fraction, whichever side of 0.5); a diagonal
//    one-particle gap stays open (the links are the 8-neighbourhood), a gap
//    with a hole of two spacings does not (no link that long);
//  - wedge (lattice rows along either side): the band that cuts off the
//    apex, where the wedge is one particle wide; a band side to side at
//    r = 5 closes, a band reaching one side only does not; fixed particles
//    (index >= n_free) take no part;
//  - the axis particle (nearest the origin) frozen: closed;
//  - ClosureWatch: contact (b = 0.5) and closure (b = 0) interpolated
//    between observations are exact for a gap freezing linearly in time
//    (values below 0 included) and within the chord error for a quadratic
//    one; while b >= 1 the detector is skipped between checks min_interval
//    apart; the step limit while the gap freezes follows b's last rate.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "post/closure.hpp"
#include "particles/vec.hpp"

using frostwall::post::ClosureDetector;
using frostwall::post::ClosureWatch;
using Vec2 = frostwall::particles::Vec<2>;

namespace {

// Square lattice (i d, j d) clipped to the disc r <= R: the origin is a
// particle, the unique one nearest the axis.
struct Disc {
  static constexpr double d = 0.25, R = 8.0;
  std::vector<Vec2> p;
  std::vector<long> i, j;  // lattice indices
  Disc() {
    const long n = std::lround(R / d);
    for (long a = -n; a <= n; ++a)
      for (long b = -n; b <= n; ++b)
        if (std::hypot(a * d, b * d) <= R) {
          p.emplace_back(a * d, b * d);
          i.push_back(a);
          j.push_back(b);
        }
  }
  std::size_t size() const { return p.size(); }
  // Liquid fraction 0 on the ring 4.5 < r < 5.5, 1 elsewhere.
  std::vector<double> ring() const {
    std::vector<double> f(size(), 1.0);
    for (std::size_t k = 0; k < size(); ++k)
      if (const double r = p[k].norm(); r > 4.5 && r < 5.5) f[k] = 0.0;
    return f;
  }
  bool in_ring(std::size_t k) const { return p[k].norm() > 4.5 && p[k].norm() < 5.5; }
  // The gap: the ring particles on the positive y axis, (0, 4.75), (0, 5),
  // (0, 5.25); (0, 4.5) and (0, 5.5) are just off the ring, unfrozen.
  std::vector<std::size_t> column_gap() const {
    std::vector<std::size_t> g;
    for (std::size_t k = 0; k < size(); ++k)
      if (i[k] == 0 && j[k] > 0 && in_ring(k)) g.push_back(k);
    return g;
  }
};

constexpr double wedge_angle = 2.0 * std::numbers::pi / 52.0;  // 6.923 deg

// Square lattice of spacing d, half a spacing off one side of the wedge
// 0 < theta < wedge_angle (rows along the first side, theta = 0, or along the
// second, theta = wedge_angle), clipped to r < R. Optionally followed by a
// layer of fixed particles (index >= n_free) half a spacing outside the
// first side, from the apex to beyond R.
struct Wedge {
  static constexpr double d = 0.05, R = 6.0;
  std::vector<Vec2> p;
  std::size_t n_free = 0;
  Wedge(bool rows_along_second_side, bool fixed_layer) {
    const double phi = rows_along_second_side ? wedge_angle : 0.0;
    const double sign = rows_along_second_side ? -1.0 : 1.0;  // the wedge lies below the second side
    const double c = std::cos(phi), s = std::sin(phi);
    const long n = std::lround(R / d) + 2;
    for (long a = 0; a <= n; ++a)
      for (long b = 0; b <= n; ++b) {
        const double x = (a + 0.5) * d, y = sign * (b + 0.5) * d;
        const Vec2 q(c * x - s * y, s * x + c * y);
        const double theta = std::atan2(q.y(), q.x());
        if (theta > 0.0 && theta < wedge_angle && q.norm() < R) p.push_back(q);
      }
    n_free = p.size();
    if (fixed_layer)
      for (long a = 0; a <= n; ++a) p.emplace_back((a + 0.5) * d, -0.5 * d);
  }
  std::vector<double> field(const std::function<bool(const Vec2&)>& frozen) const {
    std::vector<double> f(p.size(), 1.0);
    for (std::size_t k = 0; k < n_free; ++k)
      if (frozen(p[k])) f[k] = 0.0;
    return f;
  }
  ClosureDetector detector() const { return ClosureDetector(p, n_free, d, R); }
};

double theta(const Vec2& x) { return std::atan2(x.y(), x.x()); }

}  // namespace

TEST_CASE("closure: a frozen ring around the axis is closed, b = 0", "[freezing][closure]") {
  const Disc disc;
  const ClosureDetector detector(disc.p, disc.size(), Disc::d, Disc::R);
  const auto f = disc.ring();

  // All ground unfrozen: wide open, b is the largest level.
  CHECK(detector.bottleneck(std::vector<double>(disc.size(), 1.0)) == 1.0);
  CHECK_FALSE(detector.touching(std::vector<double>(disc.size(), 1.0)));

  // The ring: no unfrozen connection, the first frozen particle joining the
  // two sides completes it at its own level, 0.
  CHECK(detector.bottleneck(f) == 0.0);
  CHECK(detector.touching(f));

  // Ring frozen to 0.2 instead of 0: b is that level, not 0.
  auto g = f;
  for (std::size_t k = 0; k < disc.size(); ++k)
    if (disc.in_ring(k)) g[k] = 0.2;
  CHECK(detector.bottleneck(g) == 0.2);

  // Unfrozen ground beyond the far-field band only matters through the band:
  // the ring moved outward to 6.5 < r < 7.5 still closes.
  std::vector<double> outer(disc.size(), 1.0);
  for (std::size_t k = 0; k < disc.size(); ++k)
    if (disc.p[k].norm() > 6.5 && disc.p[k].norm() < 7.5) outer[k] = 0.0;
  CHECK(detector.bottleneck(outer) == 0.0);

  // The far field is the particles within 1.5 spacings of the circle,
  // r > 8 - 0.375 = 7.625: ground frozen from r = 7.7 to the edge leaves
  // those at 7.625 < r < 7.7 unfrozen and reachable (open); frozen from
  // r = 7.6 it covers them all (closed).
  auto frozen_beyond = [&](double r0) {
    std::vector<double> h(disc.size(), 1.0);
    for (std::size_t k = 0; k < disc.size(); ++k)
      if (disc.p[k].norm() >= r0) h[k] = 0.0;
    return h;
  };
  std::size_t thin_band = 0;
  for (const auto& x : disc.p) thin_band += x.norm() > 7.625 && x.norm() < 7.7;
  REQUIRE(thin_band > 0);
  CHECK(detector.bottleneck(frozen_beyond(7.7)) == 1.0);
  CHECK(detector.bottleneck(frozen_beyond(7.6)) == 0.0);

  // No particles at all on 4.5 < r < 5 (a hole wider than a link): nothing
  // joins the axis to the far field at any level, reported as b = -inf
  // (closed below every level, also below 0).
  std::vector<Vec2> holed;
  for (const auto& x : disc.p)
    if (x.norm() <= 4.5 || x.norm() >= 5.0) holed.push_back(x);
  const ClosureDetector cut(holed, holed.size(), Disc::d, Disc::R);
  CHECK(cut.bottleneck(std::vector<double>(holed.size(), 1.0)) == -std::numeric_limits<double>::infinity());
}

TEST_CASE("closure: a one-particle gap through the ring sets b to its liquid fraction", "[freezing][closure]") {
  const Disc disc;
  const ClosureDetector detector(disc.p, disc.size(), Disc::d, Disc::R);
  const auto gap = disc.column_gap();
  REQUIRE(gap.size() == 3);  // (0, 4.75), (0, 5), (0, 5.25)

  auto with_gap = [&](double level) {
    auto f = disc.ring();
    for (std::size_t k : gap) f[k] = level;
    return f;
  };
  CHECK(detector.bottleneck(with_gap(1.0)) == 1.0);
  CHECK_FALSE(detector.touching(with_gap(1.0)));
  CHECK(detector.bottleneck(with_gap(0.7)) == 0.7);
  CHECK_FALSE(detector.touching(with_gap(0.7)));
  CHECK(detector.bottleneck(with_gap(0.3)) == 0.3);
  CHECK(detector.touching(with_gap(0.3)));
  CHECK(detector.bottleneck(with_gap(0.5)) == 0.5);  // frozen means f <= 0.5
  CHECK(detector.touching(with_gap(0.5)));

  // The gap is as open as its most frozen particle.
  auto f = with_gap(0.9);
  f[gap[1]] = 0.6;
  CHECK(detector.bottleneck(f) == 0.6);

  // A notch that does not cross the ring (the outer particle of the column
  // frozen) leaves it closed.
  f = with_gap(1.0);
  f[gap[2]] = 0.0;
  CHECK(detector.bottleneck(f) == 0.0);

  // Two gaps: the more open one counts.
  f = with_gap(0.55);
  for (std::size_t k = 0; k < disc.size(); ++k)
    if (disc.i[k] == 0 && disc.j[k] < 0 && disc.in_ring(k)) f[k] = 0.8;
  CHECK(detector.bottleneck(f) == 0.8);
}

TEST_CASE("closure: links are the lattice's 8-neighbourhood (up to 1.5 spacings)", "[freezing][closure]") {
  const Disc disc;
  const ClosureDetector detector(disc.p, disc.size(), Disc::d, Disc::R);

  // Diagonal gap: the ring particles (k d, k d), k = 13, 14, 15 (r = 4.60,
  // 4.95, 5.30), between (12 d, 12 d) (r = 4.24) and (16 d, 16 d) (r = 5.66).
  // Their side neighbours (k d, (k+1) d) and ((k+1) d, k d) for k = 13..15
  // are on the ring (r = 4.78, 5.13, 5.48), so the gap holds only through
  // diagonal links (sqrt 2 spacings): open with the 8-neighbourhood, closed
  // with the 4-neighbourhood.
  auto f = disc.ring();
  std::vector<std::size_t> diagonal;
  for (std::size_t k = 0; k < disc.size(); ++k) {
    if (disc.i[k] == disc.j[k] && disc.i[k] > 0 && disc.in_ring(k)) diagonal.push_back(k);
    const long a = disc.i[k], b = disc.j[k];
    if (((a == b + 1) || (b == a + 1)) && std::min(a, b) >= 13 && std::min(a, b) <= 15) REQUIRE(disc.in_ring(k));
  }
  REQUIRE(diagonal.size() == 3);
  for (std::size_t k : diagonal) f[k] = 1.0;
  CHECK(detector.bottleneck(f) == 1.0);
  for (std::size_t k : diagonal) f[k] = 0.7;
  CHECK(detector.bottleneck(f) == 0.7);

  // Column gap with its middle particle (0, 5) frozen: (0, 4.75) and
  // (0, 5.25) are two spacings apart, not linked -> closed.
  f = disc.ring();
  const auto gap = disc.column_gap();
  f[gap[0]] = f[gap[2]] = 1.0;
  CHECK(detector.bottleneck(f) == 0.0);

  // A knight's-move chain (steps (d, 2d), sqrt 5 spacings): the ring
  // particle (9 d, 18 d) (r = 5.03) unfrozen between (8 d, 16 d) (r = 4.47)
  // and (10 d, 20 d) (r = 5.59): all its 8 neighbours are frozen -> closed.
  f = disc.ring();
  for (std::size_t k = 0; k < disc.size(); ++k)
    if (disc.i[k] == 9 && disc.j[k] == 18) f[k] = 1.0;
  CHECK(detector.bottleneck(f) == 0.0);
}

TEST_CASE("closure: the particle nearest the axis frozen closes", "[freezing][closure]") {
  const Disc disc;
  const ClosureDetector detector(disc.p, disc.size(), Disc::d, Disc::R);
  std::size_t origin = disc.size();
  for (std::size_t k = 0; k < disc.size(); ++k)
    if (disc.i[k] == 0 && disc.j[k] == 0) origin = k;
  REQUIRE(origin < disc.size());

  std::vector<double> f(disc.size(), 1.0);
  f[origin] = 0.0;
  CHECK(detector.bottleneck(f) == 0.0);
  CHECK(detector.touching(f));
  f[origin] = 0.4;  // b never exceeds the axis particle's own level
  CHECK(detector.bottleneck(f) == 0.4);
  f[origin] = 0.6;
  CHECK(detector.bottleneck(f) == 0.6);
  CHECK_FALSE(detector.touching(f));

  // A lattice shifted off the axis: the nearest particle is (0.3 d, 0.1 d),
  // one particle; freezing it closes, freezing its neighbour (-0.7 d, 0.1 d)
  // (r = 0.18 against 0.08) does not.
  const double d = Disc::d;
  std::vector<Vec2> p;
  std::size_t nearest = 0, next = 0;
  for (long a = -20; a <= 20; ++a)
    for (long b = -20; b <= 20; ++b) {
      const Vec2 x((a + 0.3) * d, (b + 0.1) * d);
      if (x.norm() > 5.0) continue;
      if (a == 0 && b == 0) nearest = p.size();
      if (a == -1 && b == 0) next = p.size();
      p.push_back(x);
    }
  const ClosureDetector shifted(p, p.size(), d, 5.0);
  std::vector<double> g(p.size(), 1.0);
  g[nearest] = 0.0;
  CHECK(shifted.bottleneck(g) == 0.0);
  g[nearest] = 1.0;
  g[next] = 0.0;
  CHECK(shifted.bottleneck(g) == 1.0);
}

TEST_CASE("closure: wedge, band across the apex, side to side, one side only", "[freezing][closure]") {
  const bool rows_along_second = GENERATE(false, true);
  const bool fixed_layer = GENERATE(false, true);
  CAPTURE(rows_along_second, fixed_layer);
  const Wedge w(rows_along_second, fixed_layer);
  const auto detector = w.detector();

  // Near the apex the wedge is one particle wide: the free particles with
  // r < 0.35 are at r = 0.226 (the axis particle), 0.276 and 0.326, in a
  // row one spacing apart (the next row starts at r = 0.63).
  std::vector<double> near;
  for (std::size_t k = 0; k < w.n_free; ++k)
    if (w.p[k].norm() < 0.35) near.push_back(w.p[k].norm());
  std::sort(near.begin(), near.end());
  REQUIRE(near.size() == 3);
  CHECK(near[0] == Approx(std::hypot(0.225, 0.025)).epsilon(1e-12));
  CHECK(near[1] == Approx(std::hypot(0.275, 0.025)).epsilon(1e-12));
  CHECK(near[2] == Approx(std::hypot(0.325, 0.025)).epsilon(1e-12));

  CHECK(detector.bottleneck(w.field([](const Vec2&) { return false; })) == 1.0);

  // Band r < 0.3: the axis particle and its neighbour frozen. The axis is
  // the particle nearest the origin, which the band cuts off: closed.
  CHECK(detector.bottleneck(w.field([](const Vec2& x) { return x.norm() < 0.3; })) == 0.0);
  // Only the axis particle's neighbour frozen (0.25 < r < 0.3): the axis
  // particle is unfrozen but cut off: closed.
  CHECK(detector.bottleneck(w.field([](const Vec2& x) { return x.norm() > 0.25 && x.norm() < 0.3; })) == 0.0);
  // Same one particle further out (0.3 < r < 0.35): closed as well.
  CHECK(detector.bottleneck(w.field([](const Vec2& x) { return x.norm() > 0.3 && x.norm() < 0.35; })) == 0.0);

  // Band 4.9 < r < 5.1 (4 spacings thick) from side to side: closed.
  auto band = [](const Vec2& x) { return x.norm() > 4.9 && x.norm() < 5.1; };
  CHECK(detector.bottleneck(w.field(band)) == 0.0);
  // Reaching only the first side (theta < 0.6 wedge) or only the second
  // (theta > 0.4 wedge): at r = 5 the wedge is 12 spacings wide, the
  // remaining 0.4 of it (~5 spacings) is an open passage.
  CHECK(detector.bottleneck(w.field([&](const Vec2& x) { return band(x) && theta(x) < 0.6 * wedge_angle; })) == 1.0);
  CHECK(detector.bottleneck(w.field([&](const Vec2& x) { return band(x) && theta(x) > 0.4 * wedge_angle; })) == 1.0);
  // The side-to-side band with its last particle column at the second side
  // partly thawed (0.8): the passage along that side sets b.
  // Thawed: the band's particles less than one spacing from the second side
  // (an 8-connected strip on either lattice).
  auto f = w.field(band);
  std::size_t thawed = 0;
  for (std::size_t k = 0; k < w.n_free; ++k)
    if (band(w.p[k]) && w.p[k].norm() * std::sin(wedge_angle - theta(w.p[k])) < Wedge::d) {
      f[k] = 0.8;
      ++thawed;
    }
  REQUIRE(thawed > 0);
  CHECK(detector.bottleneck(f) == 0.8);
}

TEST_CASE("closure: ClosureWatch interpolates contact (b = 0.5) and closure (b = 0)", "[freezing][closure]") {
  // The watch is fed g = H / H_latent, unclamped: 1 at the start of
  // freezing, 0 fully frozen, negative once colder. The gap's g falls and
  // crosses 0.5 (the columns touch) and then 0 (closure).
  const Disc disc;
  const ClosureDetector detector(disc.p, disc.size(), Disc::d, Disc::R);
  const auto gap = disc.column_gap();
  // The rest of the ring well below 0 (fully frozen and colder), so the
  // gap alone decides both levels.
  auto field = [&](double level) {
    auto f = disc.ring();
    for (auto& v : f)
      if (v == 0.0) v = -1.0;
    for (std::size_t k : gap) f[k] = level;
    return f;
  };
  const double T0 = 3.7;

  SECTION("gap freezing linearly in time: both exact") {
    // g(t) = 1 - t / T0 crosses 0.5 at T0 / 2 = 1.85 and 0 at T0 = 3.7;
    // dt = 0.07 divides neither (26.43 and 52.86 steps).
    const double dt = 0.07;
    ClosureWatch watch(detector);
    long k = 0;
    for (; k < 100 && !watch.closure_time(); ++k) {
      const double t = k * dt;
      watch.observe(t, field(1.0 - t / T0), 0.0);
      if (!watch.closure_time()) CHECK(watch.last_open_time() == t);
      CHECK(watch.contact_time().has_value() == (k >= 27));  // touching first at 27 dt = 1.89
    }
    REQUIRE(watch.closure_time());
    CHECK(k - 1 == 53);  // closed first at 53 dt = 3.71, g = -0.0027 there
    CHECK(watch.last_open_time() == 52 * dt);
    CHECK(*watch.contact_time() == Approx(0.5 * T0).epsilon(1e-9));
    CHECK(*watch.closure_time() == Approx(T0).epsilon(1e-9));
    // Once closed it stays at that time.
    watch.observe(5.0, field(1.0), 0.0);
    CHECK(*watch.closure_time() == Approx(T0).epsilon(1e-9));
    CHECK(*watch.contact_time() == Approx(0.5 * T0).epsilon(1e-9));
  }

  SECTION("gap freezing quadratically: the chord's error, far below dt") {
    // g(t) = 1 - (t / T0)^2 crosses 0 at t* = T0. The chord between the
    // observations a < t* <= b crosses at (T0^2 + a b) / (a + b) =
    // t* - (t* - a)(b - t*) / (a + b), before t* (g is concave) by at
    // most dt^2 / (4 (a + b)).
    const double dt = 0.013;
    const double t_star = T0;
    ClosureWatch watch(detector);
    long k = 0;
    for (; k < 1000 && !watch.closure_time(); ++k) {
      const double t = k * dt;
      watch.observe(t, field(1.0 - (t / T0) * (t / T0)), 0.0);
    }
    REQUIRE(watch.closure_time());
    const double b = (k - 1) * dt, a = (k - 2) * dt;
    CHECK(k - 2 == 284);  // t* = 3.7 = 284.6 dt
    CHECK(watch.last_open_time() == a);
    const double tc = *watch.closure_time();
    CHECK(tc == Approx((T0 * T0 + a * b) / (a + b)).epsilon(1e-12));
    CHECK(tc <= t_star);
    CHECK(t_star - tc <= dt * dt / (4.0 * (a + b)) * (1.0 + 1e-9));
    CHECK(t_star - tc < 0.1 * dt);
  }

  SECTION("contact and closure within one observation: each interpolated on the same chord") {
    // g from 0.8 at t = 1 to -0.4 at t = 2: 0.5 at 1.25, 0 at 1 + 0.8 / 1.2.
    ClosureWatch watch(detector);
    watch.observe(0.0, field(1.0), 0.0);
    watch.observe(1.0, field(0.8), 0.0);
    CHECK_FALSE(watch.contact_time());
    watch.observe(2.0, field(-0.4), 0.0);
    REQUIRE(watch.contact_time());
    REQUIRE(watch.closure_time());
    CHECK(*watch.contact_time() == Approx(1.25).epsilon(1e-12));
    CHECK(*watch.closure_time() == Approx(1.0 + 0.8 / 1.2).epsilon(1e-12));
  }

  SECTION("time_to_fall: the step that lowers b by a given share at its last rate") {
    ClosureWatch watch(detector);
    watch.observe(0.0, field(1.0), 0.0);
    CHECK_FALSE(watch.time_to_fall(0.05));  // wide open: no limit
    watch.observe(1.0, field(0.9), 0.0);
    watch.observe(1.5, field(0.8), 0.0);  // falling 0.2 per unit time
    REQUIRE(watch.time_to_fall(0.05));
    CHECK(*watch.time_to_fall(0.05) == Approx(0.25).epsilon(1e-9));
    watch.observe(2.0, field(-0.1), 0.0);  // closed: no limit any more
    CHECK_FALSE(watch.time_to_fall(0.05));
  }

  SECTION("wide open: checked only every min_interval, then at every call") {
    // Gap at g = 1 until t = 1, then g = 1 - (t - 1) / 2.35: touches at
    // 2.175, closes at 3.35.
    // With min_interval = 0.25 and calls every 0.1 the open gap is checked
    // at 0, 0.3, 0.6, 0.9 (and 1.2, where it is found freezing); from then
    // on at every call, so the linear fall is interpolated exactly (the
    // g = 0.95 at 1.1 goes unseen: b was 1 at the last check).
    const double dt = 0.1;
    ClosureWatch watch(detector);
    const std::vector<double> last_open = {0, 0, 0, 3, 3, 3, 6, 6, 6, 9, 9, 9, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21};
    long k = 0;
    for (; k < 60 && !watch.closure_time(); ++k) {
      const double t = k * dt;
      CHECK(watch.due(t) == (k < 12 ? k % 3 == 0 : true));
      watch.observe(t, field(t <= 1.0 ? 1.0 : 1.0 - (t - 1.0) / 2.35), 0.25);
      if (!watch.closure_time() && k < static_cast<long>(last_open.size()))
        CHECK(watch.last_open_time() == last_open[k] * dt);
    }
    REQUIRE(watch.closure_time());
    CHECK(k - 1 == 34);  // closed first at 3.4
    CHECK(*watch.contact_time() == Approx(2.175).epsilon(1e-9));
    CHECK(*watch.closure_time() == Approx(3.35).epsilon(1e-9));
  }
}
