#include "dem/commands.hpp"

#include <fmt/core.h>

namespace frostwall::dem {

std::vector<std::string> box_commands(const Box& box, const Contact& contact, double skin) {
  auto bc = [&](int k) { return box.periodic[k] ? "p" : "f"; };
  return {"units si",
          "atom_style sphere",
          fmt::format("boundary {} {} {}", bc(0), bc(1), bc(2)),
          "newton off",
          "comm_modify vel yes",
          fmt::format("region domain block {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} units box", box.low[0],
                      box.high[0], box.low[1], box.high[1], box.low[2], box.high[2]),
          "create_box 1 domain",
          "pair_style granular",
          fmt::format("pair_coeff * * hertz/material {:.17g} {:.17g} {:.17g} tangential linear_nohistory 1.0 {:.17g}",
                      contact.youngs_modulus, contact.normal_damping, contact.poisson_ratio, contact.friction),
          fmt::format("neighbor {:.17g} bin", skin)};
}

std::vector<std::string> grain_commands(const Grain& g, long id) {
  return {fmt::format("create_atoms 1 single {:.17g} {:.17g} {:.17g} units box", g.position[0], g.position[1], g.position[2]),
          fmt::format("set atom {} diameter {:.17g} density {:.17g}", id, g.diameter, g.density)};
}

std::vector<std::string> motion_commands(double gravity, double timestep) {
  return {fmt::format("fix gravity all gravity {:.17g} vector 0 0 -1", gravity),
          fmt::format("fix {} all external pf/callback 1 1", fluid_fix),
          "fix move all nve/sphere",
          fmt::format("timestep {:.17g}", timestep)};
}

}  // namespace frostwall::dem
