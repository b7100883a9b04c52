// Story: the building blocks against independent answers. Kernels integrate
// to one and their derivative matches a finite difference; the cell list
// finds exactly the neighbours brute force finds (PySPH's check); mirror
// images fill corners and stop at each particle's own reach; the
// renormalised Laplacian is exact for a quadratic field on a lattice, where
// the plain form is off by the lattice-sum error;
// on an irregular cloud the moment-corrected weights are exact for linear
// and quadratic fields; the two-level solver under that correction agrees
// with a direct factorisation and needs as many iterations on a big
// problem as on a small one.
#include <catch2/catch.hpp>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <fmt/core.h>
#include <random>

#include "particles/mirror_images.hpp"
#include "particles/cell_list.hpp"
#include "sph/kernel.hpp"
#include "sph/laplacian.hpp"
#include "sph/moment_correction.hpp"

using namespace frostwall;
using particles::Vec;

TEST_CASE("Kernels are normalised and their derivative is consistent", "[freezing][sph]") {
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

TEST_CASE("Cell list finds the same neighbours as brute force", "[freezing][sph]") {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 3.0);
  std::vector<Vec<2>> points(2000);
  for (auto& p : points) p = Vec<2>(u(rng), 0.5 * u(rng));
  const double radius = 0.13;
  const particles::CellList<2> cells(points, radius);
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
particles::ParticleSet<2> insulated_square(int n) {
  particles::ParticleSet<2> P;
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

TEST_CASE("Mirror images: a corner particle sees its three images", "[freezing][sph]") {
  const auto P = insulated_square(10);
  const double reach = 0.15;  // the double image of the corner particle (0.05, 0.05) is 0.141 away
  const auto images = particles::mirror_images(P, reach);
  std::size_t of_corner = 0;
  for (std::size_t k = 0; k < images.source.size(); ++k)
    if ((P.position[images.source[k]] - Vec<2>(0.05, 0.05)).norm() < 1e-12) ++of_corner;
  CHECK(of_corner == 3);  // across x = 0, across y = 0, and across both
}

TEST_CASE("Mirror images: each particle's own reach bounds how far beyond a plane its images go", "[freezing][sph]") {
  // Own reach 1.5 spacings for the left half of the square, 3 for the right:
  // the images kept are those of the full list that lie no further than
  // their source's own reach beyond every plane, no more, no fewer.
  const int n = 20;
  const auto P = insulated_square(n);
  const double d = 1.0 / n, reach = 4 * d;
  std::vector<double> own(P.size());
  for (std::size_t j = 0; j < P.size(); ++j) own[j] = (P.position[j][0] < 0.5 ? 1.5 : 3.0) * d;
  const auto all = particles::mirror_images(P, reach);
  const auto some = particles::mirror_images(P, reach, own);
  auto beyond = [](const Vec<2>& y) {  // distance outside the unit square, along the worst axis
    return std::max({-y[0], y[0] - 1.0, -y[1], y[1] - 1.0, 0.0});
  };
  std::size_t expected = 0;
  for (std::size_t k = 0; k < all.position.size(); ++k)
    if (beyond(all.position[k]) <= own[all.source[k]]) ++expected;
  CHECK(some.position.size() == expected);
  CHECK(expected < all.position.size());
  for (std::size_t k = 0; k < some.position.size(); ++k) CHECK(beyond(some.position[k]) <= own[some.source[k]]);
}

TEST_CASE("Renormalised Laplacian is exact for a quadratic field on a lattice", "[freezing][sph]") {
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

TEST_CASE("Moment-corrected Laplacian is exact for linear and quadratic fields on an irregular cloud",
          "[freezing][sph]") {
  // The lattice shaken by up to a tenth of a spacing: the kernel sums' odd
  // moments no longer vanish, so the renormalised weights alone see a
  // gradient where there is none. Exact answers at interior particles, with
  // k_ij = 2: 0 for T = 3x - 2y, 4 for T = x^2 + y^2.
  const int n = 40;
  auto P = insulated_square(n);
  const double d = 1.0 / n, h = 1.3 * d;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shake(-0.1 * d, 0.1 * d);
  for (std::size_t i = 0; i < P.n_free; ++i) P.position[i] += Vec<2>(shake(random), shake(random));
  const sph::WendlandC2<2> kernel;
  auto worst_errors = [&](bool correct) {
    const auto pairs =
        sph::build_laplacian_pairs<2>(P, kernel, {h, project::LaplacianForm::renormalised, false, correct});
    double linear = 0.0, quadratic = 0.0;
    for (std::size_t i = 0; i < P.n_free; ++i) {
      const auto& x = P.position[i];
      if (std::min({x[0], x[1], 1 - x[0], 1 - x[1]}) < 0.2) continue;
      double lap_linear = 0.0, lap_quadratic = 0.0;
      for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
        const Vec<2> dx = P.position[pairs.column[e]] - x;
        lap_linear += pairs.weight[e] * 2.0 * (3 * dx[0] - 2 * dx[1]);
        lap_quadratic += pairs.weight[e] * 2.0 * (P.position[pairs.column[e]].squaredNorm() - x.squaredNorm());
      }
      // The linear field's error in units of its gradient per spacing.
      linear = std::max(linear, std::abs(lap_linear) * d / std::sqrt(13.0));
      quadratic = std::max(quadratic, std::abs(lap_quadratic - 4.0) / 4.0);
    }
    return std::make_pair(linear, quadratic);
  };
  const auto [plain_linear, plain_quadratic] = worst_errors(false);
  const auto [linear, quadratic] = worst_errors(true);
  fmt::print(
      "\nIrregular cloud (shaken lattice): Laplacian error of a linear field {:.1e} -> {:.1e} (per gradient/spacing), "
      "of x^2 + y^2 {:.1e} -> {:.1e} with the moment correction\n",
      plain_linear, linear, plain_quadratic, quadratic);
  CHECK(plain_linear > 1e-2);  // what the correction is for
  CHECK(linear < 1e-6);        // the moment system is solved to 1e-8
  CHECK(quadratic < 1e-6);
}

namespace {
// A shaken lattice of m x m free particles inside three layers of fixed
// ones (no mirrors, so every pair is between real particles) and its
// moment-correction system (moment_correction.hpp).
sph::MomentSystem<2> shaken_square_system(int m) {
  particles::ParticleSet<2> P;
  const double d = 1.0 / m;
  P.spacing = d;
  std::mt19937 random(11);
  std::uniform_real_distribution<double> shake(-0.1 * d, 0.1 * d);
  for (int j = -3; j < m + 3; ++j)
    for (int i = -3; i < m + 3; ++i) {
      const bool free = i >= 0 && j >= 0 && i < m && j < m;
      const Vec<2> x((i + 0.5) * d, (j + 0.5) * d);
      P.add(free ? Vec<2>(x + Vec<2>(shake(random), shake(random))) : x, d * d, free ? -1 : 0);
    }
  P.order_free_first();
  const sph::WendlandC2<2> kernel;
  const double h = 1.3 * d;
  const auto pairs = sph::build_laplacian_pairs<2>(P, kernel, {h, project::LaplacianForm::renormalised, false, false});
  std::vector<Vec<2>> pair_vector(pairs.pairs());
  for (std::size_t i = 0; i < P.n_free; ++i)
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e)
      pair_vector[e] = P.position[pairs.column[e]] - P.position[i];
  return sph::moment_system<2>(pairs, P.position, P.volume, pair_vector,
                               std::vector<Eigen::Matrix2d>(pairs.pairs(), Eigen::Matrix2d::Identity()),
                               std::vector<double>(P.n_free, h));
}
}  // namespace

TEST_CASE("Two-level block CG agrees with a direct solve, and its iterations do not grow with the cloud",
          "[freezing][sph]") {
  int iterations[2];
  const int sizes[2] = {30, 90};
  for (int s = 0; s < 2; ++s) {
    const auto system = shaken_square_system(sizes[s]);
    const auto& K = system.K;
    REQUIRE(K.rows() == std::size_t(sizes[s] * sizes[s]));  // every particle surrounded
    const Eigen::SparseMatrix<double> A = K.sparse();
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> direct(A);
    REQUIRE(direct.info() == Eigen::Success);
    const Eigen::VectorXd exact = direct.solve(system.rhs);
    Eigen::VectorXd z;
    sph::TwoLevelReport report;
    const bool converged = sph::solve_two_level(K, system.rhs, system.near_null, 1e-8, 1000, z, &report);
    INFO("iterations " << report.iterations << ", residual " << report.relative_residual);
    REQUIRE(converged);
    const double residual = (system.rhs - A * z).norm() / system.rhs.norm();
    // The error as the weights see it: (z - exact)^T A (z - exact) is the
    // squared change of the pair weights it makes.
    const Eigen::VectorXd error = z - exact;
    const double energy = std::sqrt(error.dot(A * error) / exact.dot(A * exact));
    fmt::print("\nTwo-level CG, shaken {0}x{0} cloud ({1} unknowns, {2} aggregates): {3} iterations, residual {4:.1e}, "
               "energy-norm error against LDLT {5:.1e}\n",
               sizes[s], system.rhs.size(), report.aggregates, report.iterations, residual, energy);
    CHECK(residual < 1e-8);
    CHECK(energy < 1e-6);
    iterations[s] = report.iterations;
  }
  // Nine times the unknowns: plain CG would need about three times the iterations.
  CHECK(iterations[1] < 1.5 * iterations[0]);
}
