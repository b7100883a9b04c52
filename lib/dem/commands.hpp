// The one place that turns grain-assembly settings into LAMMPS input
// lines (SI units, atom_style sphere, pair_style granular). Everything
// else in frostwall calls these; no LAMMPS syntax elsewhere.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace frostwall::dem {

struct Box {
  std::array<double, 3> low{}, high{};     // m
  std::array<bool, 3> periodic{false, false, false};
};

// Hertz contact from the material (LAMMPS `hertz/material`), Mindlin-free
// linear tangential spring with Coulomb friction.
struct Contact {
  double youngs_modulus = 1e8;   // Pa
  double poisson_ratio = 0.3;
  double normal_damping = 0.3;   // LAMMPS's damping coefficient (viscoelastic)
  double friction = 0.5;
};

struct Grain {
  std::array<double, 3> position{};  // m
  double diameter = 0.0;             // m
  double density = 0.0;              // kg/m3
};

// The box, one atom type, granular contacts, the neighbour skin.
std::vector<std::string> box_commands(const Box& box, const Contact& contact, double skin);
// The id-th grain made (1, 2, ...: LAMMPS numbers atoms in order).
std::vector<std::string> grain_commands(const Grain& grain, long id);
// Gravity along -z (m/s2), an external per-grain force (fix id
// `fluid`, pf/callback every step), velocity-Verlet for spheres, the step.
std::vector<std::string> motion_commands(double gravity, double timestep);
inline constexpr const char* fluid_fix = "fluid";

}  // namespace frostwall::dem
