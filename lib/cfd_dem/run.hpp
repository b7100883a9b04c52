// A "physics": "cfd-dem" run (run::run_project calls it): grains in LAMMPS,
// pore water on the coarse grid, coupled both ways; under mpirun the
// grains are shared among the ranks and rank 0 writes the files.
#pragma once

#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"

namespace frostwall::cfd_dem {

// The DEM step: project's, else a fifth of the smallest grain's Rayleigh time.
double dem_timestep(const project::CfdDem& c);
// DEM steps per fluid update: project's, else from the Stokes relaxation
// time and the time the flow takes to carry a grain a tenth of its size.
int coupling_interval(const project::CfdDem& c, double dt, bool flowing);
// Peak memory per grain in LAMMPS with granular history and our held
// forces, rounded up; per fluid cell with the sparse system.
inline constexpr double bytes_per_grain = 4000.0, bytes_per_cell = 2000.0;
// Throws project::ProjectError when the grains or the grid would not fit.
void check_cfd_dem_resources(const project::CfdDem& c);

summary::Summary run_cfd_dem(const project::Project& p, const project::RunOptions& options);

}  // namespace frostwall::cfd_dem
