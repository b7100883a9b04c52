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

// Hertz contact from the material (`hertz/material`), normal damping from
// the coefficient of restitution (Tsuji et al. 1992, `damping tsuji`),
// Mindlin tangential stiffness from the material with Coulomb friction,
// and optionally a rolling resistance (spring-dashpot-slider `sds`).
struct Contact {
  double youngs_modulus = 1e8;  // Pa
  double poisson_ratio = 0.3;
  double restitution = 0.5;
  double friction = 0.5;
  double rolling_friction = 0.0;  // 0: no rolling resistance
  double rolling_stiffness = 0.0;  // N m/rad per unit... LAMMPS k_roll (N/m), used when rolling_friction > 0
};

struct Grain {
  std::array<double, 3> position{};  // m
  double diameter = 0.0;             // m
  double density = 0.0;              // kg/m3
};

// Units, atom style, boundaries: what precedes the box or a data file.
// With a settle_axis (0, 1, 2) the ranks split the box only across it:
// grains settle along it, and slabs along it would leave ranks empty.
std::vector<std::string> setup_commands(const Box& box, int settle_axis = -1);
// The box and one atom type (when the grains are not read from a file).
std::vector<std::string> create_box_commands(const Box& box);
// Granular contacts between grains, walls on every non-periodic face, the
// neighbour skin, and the per-grain contact count (compute `contacts`).
std::vector<std::string> contact_commands(const Box& box, const Contact& contact, double skin);
// All three above, in order (a box without grains yet).
std::vector<std::string> box_commands(const Box& box, const Contact& contact, double skin);
// The id-th grain made (1, 2, ...: LAMMPS numbers atoms in order).
std::vector<std::string> grain_commands(const Grain& grain, long id);
// A LAMMPS data file's text (atom_style sphere) holding these grains, ids 1..n.
std::string data_file(const Box& box, const std::vector<Grain>& grains);
std::string read_data_command(const std::string& file);
std::string write_data_command(const std::string& file);
// Gravity (m/s2, any direction), an external per-grain force (fix id
// `fluid`, pf/callback every step), velocity-Verlet for spheres unless the
// grains are held, the step.
std::vector<std::string> motion_commands(const std::array<double, 3>& gravity, double timestep, bool held = false);
// Gravity along -z, as above.
std::vector<std::string> motion_commands(double gravity, double timestep);
inline constexpr const char* fluid_fix = "fluid";
inline constexpr const char* contact_compute = "contacts";

}  // namespace frostwall::dem
