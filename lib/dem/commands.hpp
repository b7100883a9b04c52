// The one place that turns grain-assembly settings into LAMMPS input
// lines (SI units, atom_style sphere, pair_style granular). Everything
// else in frostwall calls these; no LAMMPS syntax elsewhere.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace frostwall::dem {

struct Box {
  std::array<double, 3> low{}, high{};  // m
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
  double rolling_friction = 0.0;   // 0: no rolling resistance
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
// What precedes a restart file, which brings its own units, atom style,
// boundaries and box: the atom map, the ghosts' velocities, the ranks' split.
std::vector<std::string> restart_setup_commands(int settle_axis = -1);
// The box and one atom type (when the grains are not read from a file).
std::vector<std::string> create_box_commands(const Box& box);
// Neighbour lists: skin (m), steps between the moved-half-the-skin checks,
// bin size (m; 0: LAMMPS' half the cutoff).
struct Neighbour {
  double skin = 0.0;
  int every = 1;
  double bin_size = 0.0;
};

// Granular contacts between grains; walls on every non-periodic face but
// an open one (open_face 0..5, x_min .. z_max; -1 none), the neighbour
// skin, and the per-grain contact count (compute `contacts`); both.
std::vector<std::string> pair_commands(const Contact& contact);
std::vector<std::string> wall_commands(const Box& box, const Contact& contact, const Neighbour& neighbour,
                                       int open_face = -1);
std::vector<std::string> contact_commands(const Box& box, const Contact& contact, const Neighbour& neighbour,
                                          int open_face = -1);
// The contact law changed in place (pair_coeff and the walls again): the
// settling friction replaced by the run's.
std::vector<std::string> new_contact_commands(const Box& box, const Contact& contact, int open_face = -1);
// All three above, in order (a box without grains yet).
std::vector<std::string> box_commands(const Box& box, const Contact& contact, const Neighbour& neighbour);
// The id-th grain made (1, 2, ...: LAMMPS numbers atoms in order).
std::vector<std::string> grain_commands(const Grain& grain, long id);
// A LAMMPS data file's text (atom_style sphere) holding these grains, ids 1..n.
std::string data_file(const Box& box, const std::vector<Grain>& grains);
std::string read_data_command(const std::string& file);
// A restart file keeps what a data file loses: the contacts' tangential
// and rolling springs (the pair's and the walls' per-atom histories).
// After read_restart the same pair style and walls (same fix ids) pick
// their histories up again.
std::string read_restart_command(const std::string& file);
std::string write_restart_command(const std::string& file);
// A sphere (centre, radius) the grains are kept out of by a wall while
// they settle (fix `cavity_wall`), and the commands that take it away.
std::vector<std::string> cavity_wall_commands(const std::array<double, 3>& centre, double radius,
                                              const Contact& contact);
std::vector<std::string> remove_cavity_wall_commands();
// A block (low, high) the grains are held in by walls while they settle
// (fix `heap_wall`; a heap's container, lifted as the run starts), and the
// commands that take it away.
std::vector<std::string> block_wall_commands(const std::array<double, 3>& low, const std::array<double, 3>& high,
                                             const Contact& contact);
std::vector<std::string> remove_block_wall_commands();
// The block's four sides (no floor, no lid) rising at `speed` (m/s) from
// the simulated time `from_time` (s): the container lifted off a heap.
std::vector<std::string> lifted_block_commands(const std::array<double, 3>& low, const std::array<double, 3>& high,
                                               const Contact& contact, double speed, double from_time);
// The sphere as a region (`cavity_inside`, once), and the command that
// deletes every grain whose centre is in it (ids kept).
std::string cavity_region_command(const std::array<double, 3>& centre, double radius);
inline constexpr const char* delete_in_cavity = "delete_atoms region cavity_inside compress no";
// After settling in a taller column: deletes the grains whose centre lies
// above `level` along the axis, shrinks the box along it to `box`, and
// puts that axis's walls at the new faces.
std::vector<std::string> trim_commands(const Box& box, int axis, double level, const Contact& contact,
                                       int open_face = -1);
// With an open face: grains that leave the box are gone, not an error.
inline constexpr const char* lost_grains_allowed = "thermo_modify lost ignore";

// Gravity (m/s2, any direction), an external per-grain force (fix id
// `fluid`, pf/callback every step), velocity-Verlet for spheres unless the
// grains are held, the step.
std::vector<std::string> motion_commands(const std::array<double, 3>& gravity, double timestep, bool held = false);
// Gravity along -z, as above.
std::vector<std::string> motion_commands(double gravity, double timestep);
inline constexpr const char* fluid_fix = "fluid";
inline constexpr const char* contact_compute = "contacts";

}  // namespace frostwall::dem
