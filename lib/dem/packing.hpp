// Where the grains start: a jittered cubic lattice in the fill region,
// outside the cavity, filled from the bottom (along gravity) up, so the
// grains start apart and settle under gravity into a packing. Held grains
// (a fixed bed) are spread evenly over the whole fill region instead and
// may overlap: they never move, and only their volume per cell matters.
// Drawn from the seed, the same on every platform. The settled packing is
// cached (a LAMMPS data file) under a key of every setting it depends on.
#pragma once

#include <utility>

#include <filesystem>
#include <string>
#include <vector>

#include "dem/commands.hpp"
#include "project/cfd_dem.hpp"

namespace frostwall::dem {

// Mean volume of a grain (diameters uniform in [min, max]), m3.
double mean_grain_volume(const project::GrainSettings& g);
// The diameter of a sphere of that volume, m.
double mean_grain_diameter(const project::GrainSettings& g);
// A centre at x (m) lies inside the cavity's sphere grown by clearance (false without a cavity).
bool in_cavity(const project::CfdDem& c, const double* x, double clearance = 0.0);
// A heap's container: the fill region on the floor, open up to the box's top (low, high corners).
std::pair<std::array<double, 3>, std::array<double, 3>> heap_container(const project::CfdDem& c);
// The fill region's volume within the box, minus the cavity's part of it, m3 (the
// cavity's overlap found by sampling; exact when it lies inside).
double fill_volume(const project::CfdDem& c);
// The grain count the project asks for (count, or from the porosity).
long requested_grains(const project::CfdDem& c);

// Throws project::ProjectError naming grains.count (or grains.porosity)
// when the lattice cannot hold that many grains apart.
std::vector<Grain> initial_grains(const project::CfdDem& c);

// The settled packing's cache file: $FROSTWALL_CACHE, else
// $XDG_CACHE_HOME/frostwall, else ~/.cache/frostwall; named by a hash of
// the grains, box, cavity, gravity, fluid, forces, time step and settling time.
std::filesystem::path packing_cache_file(const project::CfdDem& c, double timestep, int coupling_interval);

Box dem_box(const project::CfdDem& c);
// The box grains settle in: the project's, raised to the top of a
// settling column (grains.fill above the box).
Box settling_box(const project::CfdDem& c);
bool has_settling_column(const project::CfdDem& c);
Contact dem_contact(const project::CfdDem& c);

}  // namespace frostwall::dem
