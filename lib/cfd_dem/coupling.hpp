// The two-way coupling of a CFD-DEM run: LAMMPS's grains (lib/dem) and
// the coarse fluid grid (lib/pore_water). Every coupling step, each MPI
// rank deposits its own grains on the small replicated grid, one
// Allreduce combines the sums, every rank solves the same flow, and each
// grain's fluid force is found from the grid and held for the next
// `interval` DEM steps (added every step through LAMMPS's fix external).
// With the semi-implicit drag (the default) what is held of the drag is its
// coefficient K and fluid velocity u, and every step applies K (u - v) at
// the grain's velocity v of that step: the held force then cannot
// overshoot however short the drag's relaxation time m / K.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "dem/commands.hpp"
#include "dem/lammps_session.hpp"
#include "pore_water/fluid_grid.hpp"
#include "pore_water/grain_forces.hpp"
#include "project/cfd_dem.hpp"

namespace frostwall::cfd_dem {

// Sums over all grains of all ranks at one moment (after an Allreduce).
struct GrainTotals {
  double count = 0.0, volume = 0.0, contacts = 0.0;
  double in_cavity = 0.0;                                // grains whose centre lies in the cavity: out of the soil
  std::array<double, 3> position_sum{}, velocity_sum{};  // volume-weighted sums
  std::array<std::array<double, 3>, 3> force{};          // by kind: drag, pressure gradient, buoyancy (N)
};

class CfdDemCoupling {
 public:
  CfdDemCoupling(const project::CfdDem& c, dem::LammpsSession& lammps);
  // Deposits, solves the flow (inflow velocity as given), finds and holds
  // every local grain's fluid force. Returns the fluid solve's report.
  pore_water::SolveReport update(double inflow_velocity);
  // Without the grid: gravity's partner only, the buoyancy (grains settling
  // in a column the grid does not reach).
  void hold_buoyancy_only();
  // Runs `steps` DEM steps with the held forces.
  void advance(long steps);
  GrainTotals totals() const;  // collective: every rank must call it
  const pore_water::FluidGrid& grid() const { return grid_; }
  // The held fluid force (sum of all kinds) of a local grain by id, and by kind.
  std::array<double, 3> fluid_force(int id) const;
  const std::array<std::array<double, 3>, 3>& force_by_kind(int id) const;
  double coupling_seconds() const { return coupling_seconds_; }
  // The shortest relaxation times among all grains at the last update (s;
  // infinite without a drag): a grain's own drag, m / K, and the bed's
  // through the water's resistance, rho_p / beta (beta the grid's Ergun /
  // Wen-Yu resistance, -grad p = beta U_slip: grains that move together
  // drive the water through their neighbours' pores, and the held pressure
  // gradient answers one interval late).
  double shortest_relaxation() const { return shortest_relaxation_[0]; }
  double shortest_bed_relaxation() const { return shortest_relaxation_[1]; }
  // Collective: the grains' kinetic energy (J, all ranks), the fastest
  // grain's speed (m/s) and the grains' mass (kg).
  struct Motion {
    double energy = 0.0, fastest = 0.0, mass = 0.0;
  };
  Motion motion() const;
  // 1 for a grain that has left the soil region (its centre in the cavity), else 0.
  double lost(const double* x) const;

 private:
  const project::CfdDem& c_;
  dem::LammpsSession& lammps_;
  pore_water::FluidGrid grid_;
  std::vector<std::unique_ptr<pore_water::FluidForce>> forces_;
  std::vector<std::array<double, 3>> held_;    // by grain id: applied as is every step
  std::vector<std::array<double, 3>> shown_;   // by grain id: the whole force at the update
  std::vector<double> drag_k_;                 // by grain id: K of a semi-implicit drag (N s/m)
  std::vector<std::array<double, 3>> drag_u_;  // by grain id: its fluid velocity (m/s)
  std::array<double, 2> shortest_relaxation_{};
  std::vector<std::array<std::array<double, 3>, 3>> by_kind_;  // by grain id
  double coupling_seconds_ = 0.0;
  void apply(int n, const int* ids, double** force) const;  // every DEM step
  void size_by_id();  // the by-id arrays reach the largest grain id (once: ids are never reused)
};

// The fluid grid's faces for a project: the flow's inflow and outflow, or
// with still water an open surface (pressure 0) on the face gravity points
// away from; walls elsewhere.
std::array<pore_water::FaceCondition, 6> fluid_faces(const project::CfdDem& c, double inflow_velocity);

}  // namespace frostwall::cfd_dem
