// Story: water-filled pores that freeze and push on the solid around them
// (pd/pore_expansion.hpp), checked against the continuum:
//  - rim_displacement: a pore pushed out radially in a disc-shaped plate
//    (free outside) gives the thick-walled cylinder's (Lame) hoop stress,
//    sigma_tt = 2 G B (1/r^2 + 1/b^2), at the rim and further out, within
//    5 %, so it falls off as 1/r^2; the pore rides on the plate (no anchor:
//    pushed off centre in a plate on rollers, it moves with the plate);
//  - ice_eigenstrain: an unconfined ice disc (no matrix) grows freely by
//    volume_change in area (a 2-D model: the volume change is an area
//    change) within 1 % and no bond breaks, however small the critical
//    stretch.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "pd/pore_expansion.hpp"
#include "pd/relaxation.hpp"
#include "pd/solid.hpp"

using namespace frostwall;
using pd::Vec2;

namespace {

constexpr double E = 25.7e9;

// Lattice points (spacing dx) of the disc of radius b around c.
pd::SolidGeometry disc(Vec2 c, double b, double dx) {
  pd::SolidGeometry g;
  const int n = static_cast<int>(std::ceil(b / dx)) + 1;
  for (int j = -n; j <= n; ++j)
    for (int i = -n; i <= n; ++i) {
      const Vec2 x = c + Vec2((i + 0.5) * dx, (j + 0.5) * dx);
      if ((x - c).norm() >= b) continue;
      g.position.push_back(x);
      g.volume.push_back(dx * dx);
    }
  g.spacing = dx;
  g.width = g.height = 2.0 * (c[0] + b);
  return g;
}

project::Mechanics free_body(std::optional<double> fracture_energy = std::nullopt) {
  project::Mechanics m;  // every side free: no ghosts
  m.material.elastic_modulus = E;
  m.material.fracture_energy = fracture_energy;
  return m;
}

double hoop(const std::array<double, 3>& s, const Vec2& d) {
  const double r = d.norm(), c = d[0] / r, sn = d[1] / r;
  return s[0] * sn * sn + s[1] * c * c - 2.0 * s[2] * sn * c;
}

// A pore of radius a and saturation S, frozen through, in a free disc of
// radius b (rim model, no fracture, no temperature change): the push it
// gives, the relaxed field, and the mean hoop stress in bands round it
// against Lame's for that push (plane strain, nu = 1/4: lambda = G;
// u = A r + B / r with sigma_rr(b) = 0 and u(a) = u_a).
struct PushedPore {
  double push = 0.0, mean_shift = 0.0;       // u_a; the plate's mean displacement
  std::vector<std::array<double, 3>> bands;  // r0, PD hoop, Lame hoop (Pa)
};

PushedPore push_pore(double saturation) {
  const double dx = 1.0, a = 8.0, b = 48.0;
  const Vec2 c(60.0, 60.0);
  const auto g = disc(c, b, dx);
  const auto m = free_body();
  pd::PdSolid solid(g, m, pd::make_bond_law(m, 3.015 * dx));
  std::vector<int> pore_of(g.position.size(), -1);
  for (std::size_t i = 0; i < pore_of.size(); ++i)
    if ((g.position[i] - c).norm() < a) pore_of[i] = 0;
  project::FreezingExpansion fe;
  fe.model = project::FreezingExpansion::Model::rim_displacement;
  pd::PoreExpansion pores(fe, E, {{c[0], c[1], a, saturation}}, pore_of);
  pores.prepare(solid);
  std::vector<double> u(2 * g.position.size(), 0.0), dT(g.position.size(), 0.0), f(g.position.size(), 0.0);
  pores.apply(solid, f, g.volume);  // every pore particle frozen
  PushedPore out;
  out.push = pores.largest_push();
  pores.shape(solid, dT, u);
  const auto r = pd::relax(solid, u, dT, 1e-9, 200000);
  REQUIRE(r.converged);
  const double G = E / 2.5, B = out.push / (a / (2.0 * b * b) + 1.0 / a);
  auto lame = [&](double rr) { return 2.0 * G * B * (1.0 / (rr * rr) + 1.0 / (b * b)); };
  const auto sigma = solid.stress(u, dT);
  for (const double r0 : {a, a + 4 * dx, 2 * a, 3 * a}) {
    double pd_sum = 0.0, exact = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < g.position.size(); ++i) {
      const Vec2 d = g.position[i] - c;
      if (d.norm() < r0 || d.norm() >= r0 + dx) continue;
      pd_sum += hoop(sigma[i], d);
      exact += lame(d.norm());
      ++count;
    }
    out.bands.push_back({r0, pd_sum / count, exact / count});
  }
  Vec2 mean = Vec2::Zero();
  for (std::size_t i = 0; i < g.position.size(); ++i) mean += Vec2(u[2 * i], u[2 * i + 1]);
  out.mean_shift = mean.norm() / g.position.size();
  return out;
}

}  // namespace

TEST_CASE("a frozen pore pushing its rim out gives the Lame hoop stress, falling off as 1/r^2", "[mechanics][frost]") {
  const double a = 8.0;
  const auto pushed = push_pore(1.0);
  const double ua = a * (std::sqrt(1.09) - 1.0);  // a full pore: the area grows by 9 %
  REQUIRE(pushed.push == Approx(ua).epsilon(1e-12));
  for (const auto& [r0, got, want] : pushed.bands) {
    INFO("band from r = " << r0 << ": PD " << got / 1e6 << " MPa, Lame " << want / 1e6 << " MPa");
    CHECK(std::abs(got / want - 1.0) < 0.05);
  }
  // The rim's mean displacement is radial: the pore moved with the plate,
  // and the plate, free, did not move as a whole.
  CHECK(pushed.mean_shift < 1e-3 * ua);
}

TEST_CASE("a partly saturated pore pushes only with what its ice cannot fit into the air", "[mechanics][frost]") {
  // Fagerlund's critical degree of saturation: ice takes 1.09 of its water's
  // volume, so a pore at S takes 1.09 S of its own. At S = 0.95 the excess
  // is 1.09 x 0.95 - 1 = 0.0355 of the area (against 0.09 full): the push
  // a (sqrt(1.0355) - 1), and Lame's hoop stress for that push, within 5 %.
  const double a = 8.0;
  const auto partial = push_pore(0.95);
  REQUIRE(partial.push == Approx(a * (std::sqrt(1.0 + (1.09 * 0.95 - 1.0)) - 1.0)).epsilon(1e-12));
  for (const auto& [r0, got, want] : partial.bands) {
    INFO("band from r = " << r0 << ": PD " << got / 1e6 << " MPa, Lame " << want / 1e6 << " MPa");
    CHECK(std::abs(got / want - 1.0) < 0.05);
  }
  // Below S_cr = 1/1.09 = 0.917 the ice fits: no push, and with no
  // temperature change no stress at all.
  const auto dry = push_pore(0.9);
  CHECK(dry.push == 0.0);
  for (const auto& [r0, got, want] : dry.bands) {
    INFO("band from r = " << r0);
    CHECK(std::abs(got) < 1e-9 * E);
    CHECK(want == 0.0);
  }
}

TEST_CASE("an unconfined ice disc grows freely by the volume change in area and stays whole", "[mechanics][frost]") {
  const double dx = 1.0, R = 12.0;
  const Vec2 c(20.0, 20.0);
  const auto g = disc(c, R, dx);
  // A critical stretch of 1e-4: any stretch the expansion caused would break bonds.
  const auto m = free_body(1e-4 * 1e-4 * 12.0 * E * 3.015 / (5.0 * std::numbers::pi));
  pd::PdSolid solid(g, m, pd::make_bond_law(m, 3.015 * dx));
  REQUIRE(solid.law().critical_stretch == Approx(1e-4));
  const std::vector<int> pore_of(g.position.size(), 0);  // all ice, no matrix
  project::FreezingExpansion fe;                         // ice_eigenstrain, 9 %
  pd::PoreExpansion pores(fe, E, {{c[0], c[1], R}}, pore_of);
  pores.prepare(solid);
  std::vector<double> u(2 * g.position.size(), 0.0), dT(g.position.size(), 0.0);
  for (double frozen : {0.5, 1.0}) {
    const std::vector<double> f(g.position.size(), 1.0 - frozen);
    pores.apply(solid, f, g.volume);
    std::size_t broken = 0;
    const auto r = pd::relax_adjusting(solid, u, dT, 1e-10, 200000, [&] {
      const std::size_t b = solid.break_bonds(u, dT);
      broken += b;
      return b > 0;
    });
    REQUIRE(r.converged);
    CHECK(broken == 0);
    // Area from the outermost particles' mean radial displacement: (1 + u_r / r)^2.
    double growth = 0.0;
    int count = 0;
    for (std::size_t i = 0; i < g.position.size(); ++i) {
      const Vec2 d = g.position[i] - c;
      if (d.norm() < R - dx) continue;
      growth += (d + Vec2(u[2 * i], u[2 * i + 1])).squaredNorm() / d.squaredNorm();
      ++count;
    }
    const double area_change = growth / count - 1.0;
    INFO("frozen " << frozen << ": area change " << area_change);
    CHECK(std::abs(area_change / (0.09 * frozen) - 1.0) < 0.01);
  }
  CHECK(solid.intact_bonds() == solid.bonds());
}

TEST_CASE("a frozen pore rides on the plate: a cooled plate on rollers contracts as if the pore were matrix",
          "[mechanics][frost]") {
  // No push (volume_change 0): the exact field is the free contraction
  // u = -(1 + nu) alpha dT x of the plane-strain plate on rollers, the pore's
  // particles (one rigid group with the matrix's thermal strain) included.
  const double dx = 1.0, L = 40.0, alpha = 1.8e-5, dT0 = -40.0;
  pd::SolidGeometry g;
  for (int j = 0; j < 40; ++j)
    for (int i = 0; i < 40; ++i) {
      g.position.emplace_back((i + 0.5) * dx, (j + 0.5) * dx);
      g.volume.push_back(dx * dx);
    }
  g.spacing = dx;
  g.width = g.height = L;
  auto m = free_body();
  m.material.thermal_expansion = alpha;
  m.left.kind = m.bottom.kind = project::Support::Kind::roller;
  pd::PdSolid solid(g, m, pd::make_bond_law(m, 3.015 * dx));
  const Vec2 c(28.0, 24.0);
  std::vector<int> pore_of(g.position.size(), -1);
  for (std::size_t i = 0; i < pore_of.size(); ++i)
    if ((g.position[i] - c).norm() < 6.0) pore_of[i] = 0;
  project::FreezingExpansion fe;
  fe.model = project::FreezingExpansion::Model::rim_displacement;
  fe.volume_change = 0.0;
  pd::PoreExpansion pores(fe, E, {{c[0], c[1], 6.0}}, pore_of);
  pores.prepare(solid);
  std::vector<double> u(2 * g.position.size(), 0.0), dT(g.position.size(), dT0), f(g.position.size(), 0.0);
  pores.apply(solid, f, g.volume);
  pores.shape(solid, dT, u);
  REQUIRE(pd::relax(solid, u, dT, 1e-10, 200000).converged);
  const double s = 1.25 * alpha * dT0;
  double worst = 0.0;
  for (std::size_t i = 0; i < g.position.size(); ++i)
    worst = std::max(worst, (Vec2(u[2 * i], u[2 * i + 1]) - s * g.position[i]).norm());
  INFO("largest error " << worst << " of " << std::abs(s) * L);
  CHECK(worst < 1e-3 * std::abs(s) * L);
}
