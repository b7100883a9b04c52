// Story: the pressure gradient of flow through a bed of grains
// (pore_water/bed_resistance.hpp) against independent numbers:
//  - CFDEMcoupling's Ergun case (d 1 mm, porosity 0.4513, bed 0.0156 m,
//    rho_f 10, nu 1.5e-4): dP = 23.0, 115.1, 230.5 Pa at U = 0.002, 0.01,
//    0.02 m/s (the reference values of the fixed-bed check, test_cfd_dem.cpp);
//  - Wen-Yu's dilute limit: the Schiller-Naumann drag of the grains in a
//    unit volume, summed grain by grain (pore_water/drag_law.hpp; the
//    drag coefficient is shared, the voidage, grain count and area not);
//  - the blend is Ergun in dense beds, Wen-Yu in dilute ones, and has no
//    jump at porosity 0.8.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "pore_water/bed_resistance.hpp"

using namespace frostwall::pore_water;

TEST_CASE("bed resistance: Ergun's pressure drop in CFDEMcoupling's fixed bed", "[cfd_dem][pore_water][verification]") {
  const Fluid fluid{10.0, 10.0 * 1.5e-4};
  const double d = 1e-3, porosity = 0.4513, length = 0.0156;
  const double U[3] = {0.002, 0.01, 0.02}, dP[3] = {23.0, 115.1, 230.5};
  for (int k = 0; k < 3; ++k) {
    INFO("U = " << U[k] << " m/s");
    CHECK(ergun_gradient(fluid, porosity, d, U[k]) * length == Approx(dP[k]).epsilon(0.005));
    CHECK(bed_gradient(fluid, porosity, d, U[k]) * length == Approx(dP[k]).epsilon(0.01));
  }
  // Odd in U: the flow reversed meets the same resistance.
  CHECK(ergun_gradient(fluid, porosity, d, -0.01) == Approx(-ergun_gradient(fluid, porosity, d, 0.01)));
}

TEST_CASE("bed resistance: Wen-Yu's dilute limit is the grains' own Schiller-Naumann drag", "[cfd_dem][pore_water]") {
  const Fluid water{1000.0, 1e-3};
  const double d = 4e-3, solid = 1e-4;  // a few grains per litre
  for (double U : {1e-4, 1e-2, 0.3}) {
    const double grains_per_volume = solid / (std::numbers::pi * d * d * d / 6.0);
    const double drag = SchillerNaumannDrag().force(water, d, 1.0, Vec3(U, 0.0, 0.0))[0];
    INFO("U = " << U << " m/s");
    CHECK(wen_yu_gradient(water, 1.0 - solid, d, U) == Approx(grains_per_volume * drag).epsilon(0.001));
  }
}

TEST_CASE("bed resistance: the blend is Ergun when dense, Wen-Yu when dilute, continuous at porosity 0.8",
          "[cfd_dem][pore_water]") {
  const Fluid water{1000.0, 1e-3};
  const double d = 4e-3, U = 0.01;
  CHECK(bed_gradient(water, 0.4, d, U) == Approx(ergun_gradient(water, 0.4, d, U)).epsilon(0.01));
  CHECK(bed_gradient(water, 0.97, d, U) == Approx(wen_yu_gradient(water, 0.97, d, U)).epsilon(0.01));
  const double below = bed_gradient(water, 0.8 - 1e-7, d, U), above = bed_gradient(water, 0.8 + 1e-7, d, U);
  CHECK(std::abs(below - above) <= 1e-4 * below);
}
