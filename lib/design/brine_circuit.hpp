// The brine's temperature along a coaxial freeze pipe in steady state: it
// goes down one channel and up the other, each channel exchanging heat with
// the other through R_channels and the annulus with the freeze pipe's wall
// through R_ground (design/coaxial_pipe.hpp). Per metre, with W = m c the
// brine's capacity rate (W/K) and T_w(z) the wall's temperature:
//
//   down:  W dT_d/dz =  g_d (T_w - T_d) + (T_u - T_d) / R_channels
//   up:   -W dT_u/dz =  g_u (T_w - T_u) + (T_d - T_u) / R_channels
//
// g = 1 / R_ground on the annulus, 0 on the inner pipe; T_d(0) = the supply,
// T_u(L) = T_d(L) where the brine turns, and T_u(0) is the return. Each of
// `cells` equal cells balances its heat with the channels' temperatures at
// its faces averaged (second order in the cell length), so the brine's heat
// gain W (T_return - T_supply) equals the heat the cells draw from the wall
// to round-off. Solved by shooting: the march down from the top is linear in
// the unknown return temperature, so two marches fix it.
#pragma once

#include <functional>
#include <vector>

#include "design/coaxial_pipe.hpp"

namespace frostwall::design {

enum class SupplyChannel { annulus, inner };

struct BrineProfile {
  std::vector<double> depth;     // the cells' faces, m (0 at the top)
  std::vector<double> down, up;  // the channels' temperatures at the faces
  std::vector<double> draw;      // W/m the wall gives the brine, per cell
  double supply = 0.0, return_temperature = 0.0;
  double heat = 0.0;  // W the brine takes up: W (return - supply)
  // The annulus' temperature at the faces (down or up, by the supply).
  const std::vector<double>& annulus(SupplyChannel s) const { return s == SupplyChannel::annulus ? down : up; }
};

BrineProfile steady_brine(double length, int cells, const CoaxialResistances& r, double capacity_rate,
                          SupplyChannel supply_channel, double supply,
                          const std::function<double(double)>& wall_temperature);

// The same circuit with the heat the ground gives the annulus prescribed
// (W per metre at depth z, as the ground's sections drew it) instead of the
// wall's temperature: R_ground then plays no part, and the brine's heat
// gain is the drawn heat's integral over the cells (midpoint rule) exactly.
BrineProfile brine_with_draw(double length, int cells, const CoaxialResistances& r, double capacity_rate,
                             SupplyChannel supply_channel, double supply, const std::function<double(double)>& draw);

}  // namespace frostwall::design
