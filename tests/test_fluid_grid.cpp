// Story: the coarse pore-water grid of the CFD-DEM model
// (pore_water/fluid_grid.hpp) against independent checks:
//  - mass: every cell's mixture flows balance and what flows in flows out,
//    for a random packing of moving grains;
//  - a uniform fixed bed gives Ergun's pressure drop, and CFDEMcoupling's
//    Ergun case numbers (23.0, 115.1, 230.5 Pa; see test_bed_resistance);
//  - deposition keeps every grain's volume in the box, also at walls and
//    corners, and sums from separate "ranks" add up;
//  - two layers in series: the drops add;
//  - no pressure face is refused.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <numbers>
#include <random>
#include <stdexcept>

#include "pore_water/bed_resistance.hpp"
#include "pore_water/fluid_grid.hpp"

using namespace frostwall::pore_water;

namespace {

double grain_volume(double d) { return std::numbers::pi * d * d * d / 6.0; }

std::array<FaceCondition, 6> flow_along(int axis, double U, double p_out = 0.0) {
  std::array<FaceCondition, 6> faces{};
  faces[2 * axis] = {FaceKind::inflow_velocity, U};
  faces[2 * axis + 1] = {FaceKind::pressure, p_out};
  return faces;
}

// One grain of the given diameter at every cell centre of the layer
// k0 <= k < k1: all its volume lands in its own cell.
void fill_layer(FluidGrid& grid, int k0, int k1, double d) {
  const auto& s = grid.shape();
  for (int k = k0; k < k1; ++k)
    for (int j = 0; j < s.cells[1]; ++j)
      for (int i = 0; i < s.cells[0]; ++i) grid.add_grain(s.centre(i, j, k), d, Vec3::Zero());
}

// The grain diameter that leaves the given porosity in a cubic cell of side h.
double diameter_for(double porosity, double h) {
  return std::cbrt(6.0 * (1.0 - porosity) * h * h * h / std::numbers::pi);
}

}  // namespace

TEST_CASE("fluid grid: mixture mass is conserved cell by cell with moving grains",
          "[cfd_dem][fluid_grid][pore_water]") {
  GridShape shape{Vec3::Zero(), Vec3(0.10, 0.08, 0.06), {10, 8, 6}};
  const Fluid water{1000.0, 1e-3};
  const double U = 0.002;
  FluidGrid grid(shape, flow_along(1, U), water, 4e-3, 0.3);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n = 0; n < 12 * shape.count(); ++n) {
    const Vec3 x(0.10 * unit(random), 0.08 * unit(random), 0.06 * unit(random));
    const Vec3 v = 0.01 * (Vec3(unit(random), unit(random), unit(random)) - Vec3::Constant(0.5));
    grid.add_grain(x, 3e-3 + 2e-3 * unit(random), v);
  }
  grid.finish_grains();
  const auto report = grid.solve(1e-13);
  const double imbalance = grid.largest_cell_imbalance() / grid.inflow();
  const double net = std::abs(grid.inflow() - grid.outflow()) / grid.inflow();
  fmt::print("fluid grid mass: {} Picard, {} CG iterations, worst cell {:.2e}, in-out {:.2e} of the inflow\n",
             report.picard_iterations, report.linear_iterations, imbalance, net);
  CHECK(report.converged);
  CHECK(imbalance < 1e-8);
  CHECK(net < 1e-8);
}

TEST_CASE("fluid grid: a uniform fixed bed gives Ergun's pressure drop",
          "[cfd_dem][fluid_grid][pore_water][verification]") {
  // CFDEMcoupling's Ergun case: d 1 mm, porosity 0.4513, bed 0.0156 m,
  // rho_f 10, nu 1.5e-4. Grains on a lattice of 2 per cell per axis; the
  // cell's width is chosen so the porosity is exactly 0.4513.
  const Fluid fluid{10.0, 10.0 * 1.5e-4};
  const double d = 1e-3, porosity = 0.4513, length = 0.0156;
  const int nz = 8, m = 2;
  const double hz = length / nz;
  const double hx = std::sqrt(m * m * m * grain_volume(d) / ((1.0 - porosity) * hz));
  GridShape shape{Vec3::Zero(), Vec3(3 * hx, 3 * hx, length), {3, 3, nz}};
  FluidGrid grid(shape, flow_along(2, 0.01), fluid, d, 0.3);
  for (int k = 0; k < m * nz; ++k)
    for (int j = 0; j < 3 * m; ++j)
      for (int i = 0; i < 3 * m; ++i)
        grid.add_grain(Vec3((i + 0.5) * hx / m, (j + 0.5) * hx / m, (k + 0.5) * hz / m), d, Vec3::Zero());
  grid.finish_grains();
  // The tent kernel folded at the walls keeps a uniform lattice uniform.
  for (double e : grid.raw_porosity()) REQUIRE(std::abs(e - porosity) < 1e-12);

  const double U[3] = {0.002, 0.01, 0.02}, published[3] = {23.0, 115.1, 230.5};
  for (int n = 0; n < 3; ++n) {
    grid.set_face(4, {FaceKind::inflow_velocity, U[n]});
    const auto report = grid.solve(1e-12);
    const double dP = grid.face_pressure(4) - grid.face_pressure(5);
    const double ergun = bed_gradient(fluid, porosity, d, U[n]) * length;
    fmt::print("fluid grid Ergun bed: U {} m/s: dP {:.4f} Pa, bed law {:.4f} Pa, published {} Pa ({} Picard)\n", U[n],
               dP, ergun, published[n], report.picard_iterations);
    INFO("U = " << U[n] << " m/s");
    CHECK(report.converged);
    CHECK(dP == Approx(ergun).epsilon(1e-6));
    CHECK(dP == Approx(published[n]).epsilon(0.005));
    const auto at_centre = grid.sample(0.5 * (shape.low + shape.high));
    CHECK(at_centre.pressure_gradient[2] == Approx(-dP / length).epsilon(1e-6));
    CHECK(at_centre.fluid_velocity[2] == Approx(U[n] / porosity).epsilon(1e-6));
    CHECK(at_centre.superficial_velocity[2] == Approx(U[n]).epsilon(1e-6));
    CHECK(std::abs(at_centre.fluid_velocity[0]) < 1e-9 * U[n]);
  }
}

TEST_CASE("fluid grid: deposition keeps every grain's volume in the box", "[cfd_dem][fluid_grid][pore_water]") {
  GridShape shape{Vec3(-0.1, 0.2, 0.0), Vec3(0.05, 0.3, 0.06), {5, 4, 3}};
  const std::array<FaceCondition, 6> faces = flow_along(0, 0.0);
  FluidGrid grid(shape, faces, Fluid{}, 5e-3, 0.3);
  auto solid_in_grid = [&](const FluidGrid& g) {
    double sum = 0.0;
    for (double e : g.raw_porosity()) sum += (1.0 - e) * shape.cell_volume();
    return sum;
  };

  // One grain at a cell centre: all of it in that cell.
  const double d = 0.01;
  grid.add_grain(shape.centre(2, 1, 1), d, Vec3(1.0, 2.0, 3.0));
  grid.finish_grains();
  const int c = shape.index(2, 1, 1);
  for (int n = 0; n < shape.count(); ++n)
    CHECK(grid.raw_porosity()[n] == Approx(n == c ? 1.0 - grain_volume(d) / shape.cell_volume() : 1.0).epsilon(1e-14));
  CHECK(grid.grain_velocity()[c].isApprox(Vec3(1.0, 2.0, 3.0), 1e-14));
  CHECK(grid.grain_diameter()[c] == Approx(d));
  CHECK(grid.grain_diameter()[0] == 5e-3);  // no grains: the default

  // Random grains, and grains right at the walls, edges and corners,
  // deposited by two "ranks" whose raw sums are then added (as Allreduce).
  FluidGrid rank0(shape, faces, Fluid{}, 5e-3, 0.3), rank1(shape, faces, Fluid{}, 5e-3, 0.3);
  grid.clear_grains();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double total = 0.0;
  for (int n = 0; n < 400; ++n) {
    Vec3 x;
    for (int a = 0; a < 3; ++a) {
      const double r = unit(random);
      // A third of the coordinates exactly on a wall.
      x[a] = r < 1.0 / 6   ? shape.low[a]
             : r < 1.0 / 3 ? shape.high[a]
                           : shape.low[a] + unit(random) * (shape.high[a] - shape.low[a]);
    }
    const double dn = 2e-3 + 6e-3 * unit(random);
    total += grain_volume(dn);
    grid.add_grain(x, dn, Vec3::Zero());
    (n % 2 ? rank1 : rank0).add_grain(x, dn, Vec3::Zero());
  }
  grid.finish_grains();
  CHECK(solid_in_grid(grid) == Approx(total).epsilon(1e-12));
  for (std::size_t n = 0; n < rank0.deposits().size(); ++n) rank0.deposits()[n] += rank1.deposits()[n];
  rank0.finish_grains();
  CHECK(solid_in_grid(rank0) == Approx(total).epsilon(1e-12));
  for (int n = 0; n < shape.count(); ++n)
    CHECK(rank0.raw_porosity()[n] == Approx(grid.raw_porosity()[n]).epsilon(1e-12));
  // Clamping applies to the porosity used by the flow, not the raw one.
  const auto [lo, hi] = std::minmax_element(grid.porosity().begin(), grid.porosity().end());
  CHECK(*lo >= 0.3);
  CHECK(*hi <= 1.0);
}

TEST_CASE("fluid grid: the pressure drops of two layers in series add", "[cfd_dem][fluid_grid][pore_water]") {
  // Layers of porosity 0.40 (4 cells) and 0.55 (6 cells) along z, one grain
  // per cell at its centre so each layer's porosity is exactly uniform (the
  // tent kernel would otherwise blend the two across the interface). The
  // flow is one-dimensional, so the drop is exact up to the solver
  // tolerances at any speed, not only at low speed: the face between the
  // layers carries half a cell of each layer's resistance.
  const Fluid water{1000.0, 1e-3};
  const double h = 2e-3, eA = 0.40, eB = 0.55;
  const double dA = diameter_for(eA, h), dB = diameter_for(eB, h);
  GridShape shape{Vec3::Zero(), Vec3(3 * h, 3 * h, 10 * h), {3, 3, 10}};
  FluidGrid grid(shape, flow_along(2, 1e-4), water, 1e-3, 0.3);
  fill_layer(grid, 0, 4, dA);
  fill_layer(grid, 4, 10, dB);
  grid.finish_grains();
  for (double U : {1e-4, 0.05}) {
    grid.set_face(4, {FaceKind::inflow_velocity, U});
    const auto report = grid.solve(1e-12);
    const double dP = grid.face_pressure(4) - grid.face_pressure(5);
    const double sum = bed_gradient(water, eA, dA, U) * 4 * h + bed_gradient(water, eB, dB, U) * 6 * h;
    fmt::print("fluid grid series: U {} m/s: dP {:.6g} Pa, sum of the layers {:.6g} Pa ({} Picard)\n", U, dP, sum,
               report.picard_iterations);
    INFO("U = " << U << " m/s");
    CHECK(report.converged);
    CHECK(dP == Approx(sum).epsilon(1e-6));
  }
}

TEST_CASE("fluid grid: a box without a pressure face is refused", "[cfd_dem][fluid_grid][pore_water]") {
  GridShape shape{Vec3::Zero(), Vec3::Ones(), {2, 2, 2}};
  std::array<FaceCondition, 6> closed{};
  closed[0] = {FaceKind::inflow_velocity, 0.01};
  CHECK_THROWS_AS(FluidGrid(shape, closed, Fluid{}, 1e-3, 0.3), std::invalid_argument);
  FluidGrid grid(shape, flow_along(0, 0.01), Fluid{}, 1e-3, 0.3);
  CHECK_THROWS_AS(grid.set_face(1, {FaceKind::wall, 0.0}), std::invalid_argument);
  CHECK(grid.solve().converged);  // the refused change left the outlet in place
  CHECK(grid.outflow() == Approx(grid.inflow()).epsilon(1e-8));
}
