// Story: the building blocks against independent answers. Kernels integrate
// to one and their derivative matches a finite difference; the cell list
// finds exactly the neighbours brute force finds (PySPH's check); mirror
// images fill corners; the renormalised Laplacian is exact for a quadratic
// field on a lattice, where the plain form is off by the lattice-sum error.
#include <catch2/catch.hpp>
#include <algorithm>
#include <fmt/core.h>
#include <random>

#include "sph/cell_list.hpp"
#include "sph/kernel.hpp"
#include "sph/laplacian.hpp"

using namespace frostwall;
using sph::Vec;

TEST_CASE("Kernels are normalised and their derivative is consistent", "[sph]") {
  const sph::WendlandC2<2> wendland;
  const sph::CubicSpline<2> spline;
  for (const sph::Kernel* k : {static_cast<const sph::Kernel*>(&wendland), static_cast<const sph::Kernel*>(&spline)}) {
    const double h = 0.7;
    // Integral over the plane by the midpoint rule in r: 2 pi r W(r) dr.
    double integral = 0.0;
    const int n = 20000;
    const double dr = 2 * h / n;
    for (int i = 0; i < n; ++i) {
      const double r = (i + 0.5) * dr;
      integral += 2 * M_PI * r * k->value(r, h) * dr;
    }
    CHECK(integral == Approx(1.0).epsilon(1e-6));
    for (double r : {0.1, 0.5, 0.9, 1.2, 1.3}) {
      const double fd = (k->value(r + 1e-6, h) - k->value(r - 1e-6, h)) / 2e-6;
      CHECK(k->derivative(r, h) == Approx(fd).epsilon(1e-5));
    }
    CHECK(k->value(2 * h, h) == 0.0);
  }
}

TEST_CASE("Cell list finds the same neighbours as brute force", "[sph]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 3.0);
  std::vector<Vec<2>> points(2000);
  for (auto& p : points) p = Vec<2>(u(rng), 0.5 * u(rng));
  const double radius = 0.13;
  const sph::CellList<2> cells(points, radius);
  for (std::size_t i = 0; i < points.size(); i += 37) {
    std::vector<std::uint32_t> found, brute;
    cells.for_each_within(points[i], radius, [&](std::uint32_t j, double) { found.push_back(j); });
    for (std::size_t j = 0; j < points.size(); ++j)
      if ((points[j] - points[i]).norm() < radius) brute.push_back(static_cast<std::uint32_t>(j));
    std::sort(found.begin(), found.end());
    CHECK(found == brute);
  }
}

namespace {
// A square block of lattice particles [0,1]^2, all free, insulated.
sph::ParticleSet<2> insulated_square(int n) {
  sph::ParticleSet<2> P;
  const double d = 1.0 / n;
  P.spacing = d;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) P.add(Vec<2>((i + 0.5) * d, (j + 0.5) * d), d * d, -1);
  using V = Vec<2>;
  P.mirrors = {{V(0, 0), V(1, 0)}, {V(1, 0), V(1, 0)}, {V(0, 0), V(0, 1)}, {V(0, 1), V(0, 1)}};
  P.order_free_first();
  return P;
}
}  // namespace

TEST_CASE("Mirror images: a corner particle sees its three images", "[sph]") {
  const auto P = insulated_square(10);
  const double reach = 0.15;  // the double image of the corner particle (0.05, 0.05) is 0.141 away
  const auto images = sph::mirror_images(P, reach);
  std::size_t of_corner = 0;
  for (std::size_t k = 0; k < images.source.size(); ++k)
    if ((P.position[images.source[k]] - Vec<2>(0.05, 0.05)).norm() < 1e-12) ++of_corner;
  CHECK(of_corner == 3);  // across x = 0, across y = 0, and across both
}

TEST_CASE("Renormalised Laplacian is exact for a quadratic field on a lattice", "[sph]") {
  // Interior particles of a large lattice (far from the mirrors): apply the
  // operator with k_ij = 2 (unit conductivity) to T = x^2 + 3 y^2.
  const int n = 40;
  const auto P = insulated_square(n);
  const sph::WendlandC2<2> kernel;
  const double h = 1.3 / n;
  for (auto form : {project::LaplacianForm::renormalised, project::LaplacianForm::plain}) {
    const auto pairs = sph::build_laplacian_pairs<2>(P, kernel, {h, form, false});
    double worst = 0.0;
    for (std::size_t i = 0; i < P.n_free; ++i) {
      const auto& x = P.position[i];
      if (std::min({x[0], x[1], 1 - x[0], 1 - x[1]}) < 0.2) continue;
      double lap = 0.0;
      auto T = [&](const Vec<2>& y) { return y[0] * y[0] + 3 * y[1] * y[1]; };
      for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e)
        lap += pairs.weight[e] * 2.0 * (T(P.position[pairs.column[e]]) - T(x));
      worst = std::max(worst, std::abs(lap - 8.0) / 8.0);
    }
    if (form == project::LaplacianForm::renormalised) {
      CHECK(worst < 1e-10);
    } else {
      fmt::print("\nPlain SPH Laplacian on a lattice, h = 1.3 spacing: relative error {:.2f} %\n", 100 * worst);
      CHECK(worst > 1e-3);  // the lattice-sum error the renormalisation removes
    }
  }
}
