// Story: one grain settling in still fluid, through
// LAMMPS (lib/dem) with the fluid force of a drag law (lib/pore_water)
// and buoyancy added every step:
//  - a 4 mm quartz grain in water under the Dallavalle law (Di Felice at
//    porosity 1) reaches the terminal velocity of the force balance, found
//    here by bisection on the law's formula written out anew (0.391 m/s);
//  - CFDEMcoupling's settling case (d 0.1 mm, rho_p 3000, rho_f 10,
//    nu 1e-5, Schiller-Naumann): u(0.2 s) = 0.1373 m/s, within 2 %.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <numbers>

#include "dem/commands.hpp"
#include "dem/lammps_session.hpp"
#include "pore_water/drag_law.hpp"

using namespace frostwall;

namespace {

constexpr double g = 9.81;

// The grain's vertical velocity at each of `samples` times up to `end`.
std::vector<double> settle(const pore_water::DragLaw& law, const pore_water::Fluid& fluid, double d, double rho_p,
                           double end, int samples, double timestep) {
  dem::LammpsSession lammps;
  dem::Box box;
  box.low = {-5 * d, -5 * d, 0.0};
  // Tall enough for the fall (at most the Stokes speed times `end`), no
  // taller: LAMMPS bins the whole box at the grain's size.
  const double stokes = (rho_p - fluid.density) * g * d * d / (18.0 * fluid.viscosity);
  const double height = 1.5 * std::min(stokes, 2.0) * end + 10 * d;
  box.high = {5 * d, 5 * d, height};
  box.periodic = {true, true, false};
  for (const auto& c : dem::box_commands(box, dem::Contact{}, dem::Neighbour{0.1 * d})) lammps.command(c);
  for (const auto& c : dem::grain_commands({{0.0, 0.0, height - 5 * d}, d, rho_p}, 1)) lammps.command(c);
  for (const auto& c : dem::motion_commands(g, timestep)) lammps.command(c);
  const double volume = std::numbers::pi * d * d * d / 6.0;
  lammps.set_external_force(dem::fluid_fix, [&](int n, const int*, double**, double** force) {
    double** v = lammps.velocity();
    for (int i = 0; i < n; ++i) {
      // Still fluid: the slip is minus the grain's velocity.
      const pore_water::Vec3 slip(-v[i][0], -v[i][1], -v[i][2]);
      const pore_water::Vec3 F = law.force(fluid, d, 1.0, slip);
      for (int k = 0; k < 3; ++k) force[i][k] = F[k];
      force[i][2] += fluid.density * volume * g;  // buoyancy
    }
  });
  std::vector<double> u;
  const long steps = std::lround(end / samples / timestep);
  for (int s = 0; s < samples; ++s) {
    lammps.run(steps);
    u.push_back(-lammps.velocity()[0][2]);
  }
  return u;
}

}  // namespace

TEST_CASE("DEM: a 4 mm quartz grain settles in water at the Dallavalle terminal velocity",
          "[cfd_dem][dem][verification]") {
  const double d = 0.004, rho_p = 2650.0;
  const pore_water::Fluid water{1000.0, 1e-3};
  // The balance (rho_p - rho_f) g V = 1/2 Cd rho_f A u^2 with Cd =
  // (0.63 + 4.8 / sqrt(Re))^2, by bisection.
  auto excess = [&](double u) {
    const double Re = water.density * u * d / water.viscosity, Cd = std::pow(0.63 + 4.8 / std::sqrt(Re), 2);
    return (rho_p - water.density) * g * std::numbers::pi * d * d * d / 6.0 -
           0.5 * Cd * water.density * 0.25 * std::numbers::pi * d * d * u * u;
  };
  double lo = 1e-6, hi = 10.0;
  for (int it = 0; it < 200; ++it) (excess(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double terminal = 0.5 * (lo + hi);
  const auto u = settle(pore_water::DiFeliceDrag(), water, d, rho_p, 0.5, 5, 1e-5);
  fmt::print("DEM settling, 4 mm quartz in water: u = {:.4f} .. {:.4f} m/s at 0.1 .. 0.5 s; terminal {:.4f} m/s\n",
             u.front(), u.back(), terminal);
  CHECK(terminal == Approx(0.391).epsilon(0.005));
  CHECK(u.back() == Approx(terminal).epsilon(0.02));
  // It approaches from below, monotonically.
  for (std::size_t k = 1; k < u.size(); ++k) CHECK(u[k] >= u[k - 1]);
}

TEST_CASE("DEM: CFDEMcoupling's settling grain reaches 0.1373 m/s at 0.2 s under Schiller-Naumann",
          "[cfd_dem][dem][verification]") {
  const pore_water::Fluid fluid{10.0, 10.0 * 1e-5};
  const auto u = settle(pore_water::SchillerNaumannDrag(), fluid, 1e-4, 3000.0, 0.2, 4, 1e-5);
  fmt::print("DEM settling, CFDEMcoupling case: u(0.2 s) = {:.5f} m/s (reference 0.1373)\n", u.back());
  CHECK(u.back() == Approx(0.1373).epsilon(0.02));
}
