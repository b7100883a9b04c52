#include "dem/commands.hpp"

#include <cmath>
#include <fmt/core.h>

namespace frostwall::dem {

namespace {
// The contact model's words, shared by pair_coeff and the walls.
std::string contact_model(const Contact& c) {
  std::string model = fmt::format("hertz/material {} {} {} damping tsuji tangential mindlin NULL 1.0 {}",
                                  c.youngs_modulus, c.restitution, c.poisson_ratio, c.friction);
  if (c.rolling_friction > 0.0) model += fmt::format(" rolling sds {} 0.0 {}", c.rolling_stiffness, c.rolling_friction);
  return model;
}
}  // namespace

std::vector<std::string> setup_commands(const Box& box, int settle_axis) {
  auto bc = [&](int k) { return box.periodic[k] ? "p" : "f"; };
  std::vector<std::string> c = {"units si", "atom_style sphere", fmt::format("boundary {} {} {}", bc(0), bc(1), bc(2)),
                                "newton off"};
  for (auto&& s : restart_setup_commands(settle_axis)) c.push_back(std::move(s));
  return c;
}

std::vector<std::string> restart_setup_commands(int settle_axis) {
  std::vector<std::string> c = {"atom_modify map array", "comm_modify vel yes"};
  auto ranks = [&](int k) { return k == settle_axis ? "1" : "*"; };
  if (settle_axis >= 0 && settle_axis < 3)
    c.push_back(fmt::format("processors {} {} {}", ranks(0), ranks(1), ranks(2)));
  return c;
}

std::vector<std::string> create_box_commands(const Box& box) {
  return {fmt::format("region domain block {} {} {} {} {} {} units box", box.low[0], box.high[0], box.low[1],
                      box.high[1], box.low[2], box.high[2]),
          "create_box 1 domain"};
}

std::vector<std::string> pair_commands(const Contact& contact) {
  return {"pair_style granular", "pair_coeff * * " + contact_model(contact)};
}

// The walls normal to one axis (`fix wall_<axis>`); an open face has no
// plane: NULL on its side.
static std::string wall_command(const Box& box, const Contact& contact, int k, int open_face) {
  const std::string lo = open_face == 2 * k ? "NULL" : fmt::format("{}", box.low[k]);
  const std::string hi = open_face == 2 * k + 1 ? "NULL" : fmt::format("{}", box.high[k]);
  return fmt::format("fix wall_{0} all wall/gran granular {1} {0}plane {2} {3}", "xyz"[k], contact_model(contact), lo,
                     hi);
}

std::vector<std::string> wall_commands(const Box& box, const Contact& contact, const Neighbour& neighbour,
                                       int open_face) {
  std::vector<std::string> c;
  for (int k = 0; k < 3; ++k)
    if (!box.periodic[k]) c.push_back(wall_command(box, contact, k, open_face));
  c.push_back(fmt::format("neighbor {} bin", neighbour.skin));
  c.push_back(fmt::format("neigh_modify delay 0 every {} check yes", neighbour.every) +
              (neighbour.bin_size > 0.0 ? fmt::format(" binsize {}", neighbour.bin_size) : std::string()));
  c.push_back(fmt::format("compute {} all contact/atom", contact_compute));
  return c;
}

std::vector<std::string> contact_commands(const Box& box, const Contact& contact, const Neighbour& neighbour,
                                          int open_face) {
  auto c = pair_commands(contact);
  for (auto&& s : wall_commands(box, contact, neighbour, open_face)) c.push_back(std::move(s));
  if (open_face >= 0) c.push_back(lost_grains_allowed);
  return c;
}

std::vector<std::string> new_contact_commands(const Box& box, const Contact& contact, int open_face) {
  std::vector<std::string> c = {"pair_coeff * * " + contact_model(contact)};
  for (int k = 0; k < 3; ++k)
    if (!box.periodic[k]) {
      c.push_back(fmt::format("unfix wall_{}", "xyz"[k]));
      c.push_back(wall_command(box, contact, k, open_face));
    }
  return c;
}

std::vector<std::string> cavity_wall_commands(const std::array<double, 3>& x, double r, const Contact& contact) {
  return {fmt::format("region cavity_outside sphere {} {} {} {} side out units box", x[0], x[1], x[2], r),
          "fix cavity_wall all wall/gran/region granular " + contact_model(contact) + " region cavity_outside"};
}

std::vector<std::string> remove_cavity_wall_commands() { return {"unfix cavity_wall"}; }

std::vector<std::string> block_wall_commands(const std::array<double, 3>& low, const std::array<double, 3>& high,
                                             const Contact& contact) {
  return {fmt::format("region heap_block block {} {} {} {} {} {} side in units box", low[0], high[0], low[1], high[1],
                      low[2], high[2]),
          "fix heap_wall all wall/gran/region granular " + contact_model(contact) + " region heap_block"};
}

std::vector<std::string> remove_block_wall_commands() { return {"unfix heap_wall"}; }

std::vector<std::string> lifted_block_commands(const std::array<double, 3>& low, const std::array<double, 3>& high,
                                               const Contact& contact, double speed, double from_time) {
  return {fmt::format("variable heap_lift equal \"{}*(time-{})\"", speed, from_time),
          fmt::format(
              "region heap_sleeve block {} {} {} {} {} {} side in open 5 open 6 move NULL NULL v_heap_lift units box",
              low[0], high[0], low[1], high[1], low[2], high[2]),
          "fix heap_wall all wall/gran/region granular " + contact_model(contact) + " region heap_sleeve"};
}

std::string cavity_region_command(const std::array<double, 3>& x, double r) {
  return fmt::format("region cavity_inside sphere {} {} {} {} side in units box", x[0], x[1], x[2], r);
}

std::vector<std::string> trim_commands(const Box& box, int axis, double level, const Contact& contact, int open_face) {
  std::array<std::string, 6> bounds = {"INF", "INF", "INF", "INF", "INF", "INF"};
  bounds[2 * axis] = fmt::format("{}", level);
  std::vector<std::string> c = {
      fmt::format("region above block {} {} {} {} {} {} units box", bounds[0], bounds[1], bounds[2], bounds[3],
                  bounds[4], bounds[5]),
      "delete_atoms region above compress no",
      fmt::format("change_box all {} final {} {} units box", "xyz"[axis], box.low[axis], box.high[axis])};
  if (!box.periodic[axis]) {
    c.push_back(fmt::format("unfix wall_{}", "xyz"[axis]));
    c.push_back(wall_command(box, contact, axis, open_face));
  }
  return c;
}

std::vector<std::string> box_commands(const Box& box, const Contact& contact, const Neighbour& neighbour) {
  auto c = setup_commands(box);
  for (auto&& s : create_box_commands(box)) c.push_back(std::move(s));
  for (auto&& s : contact_commands(box, contact, neighbour)) c.push_back(std::move(s));
  return c;
}

std::vector<std::string> grain_commands(const Grain& g, long id) {
  return {fmt::format("create_atoms 1 single {} {} {} units box", g.position[0], g.position[1], g.position[2]),
          fmt::format("set atom {} diameter {} density {}", id, g.diameter, g.density)};
}

std::string data_file(const Box& box, const std::vector<Grain>& grains) {
  std::string text = fmt::format("frostwall grains (LAMMPS data file, atom_style sphere)\n\n{} atoms\n1 atom types\n\n",
                                 grains.size());
  for (int k = 0; k < 3; ++k) text += fmt::format("{} {} {}lo {}hi\n", box.low[k], box.high[k], "xyz"[k], "xyz"[k]);
  text += "\nAtoms # sphere\n\n";
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const auto& g = grains[i];
    text +=
        fmt::format("{} 1 {} {} {} {} {}\n", i + 1, g.diameter, g.density, g.position[0], g.position[1], g.position[2]);
  }
  return text;
}

std::string read_data_command(const std::string& file) { return "read_data " + file; }
std::string read_restart_command(const std::string& file) { return "read_restart " + file; }
std::string write_restart_command(const std::string& file) { return "write_restart " + file; }

std::vector<std::string> motion_commands(const std::array<double, 3>& g, double timestep, bool held) {
  const double magnitude = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
  std::vector<std::string> c;
  if (magnitude > 0.0)
    c.push_back(fmt::format("fix gravity all gravity {} vector {} {} {}", magnitude, g[0] / magnitude, g[1] / magnitude,
                            g[2] / magnitude));
  c.push_back(fmt::format("fix {} all external pf/callback 1 1", fluid_fix));
  if (!held) c.push_back("fix move all nve/sphere");
  c.push_back(fmt::format("timestep {}", timestep));
  return c;
}

std::vector<std::string> motion_commands(double gravity, double timestep) {
  return motion_commands({0.0, 0.0, -gravity}, timestep);
}

}  // namespace frostwall::dem
