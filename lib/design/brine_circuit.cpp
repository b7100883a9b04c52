#include "design/brine_circuit.hpp"

namespace frostwall::design {

namespace {

// A cell's exchange with the ground, per channel: g (T_wall - T) + s, the
// channel's mean temperature T over the cell.
struct Cell {
  double length;
  double g_down, g_up;  // W/(m K)
  double s_down, s_up;  // W/m
};

// One cell's two balances solved for its lower face's temperatures from its
// upper face's (d0, u0).
void march_cell(const Cell& c, double W, double k, double d0, double u0, double& d1, double& u1) {
  const double h = c.length, g_d = c.g_down, g_u = c.g_up;
  // [W + h(g_d+k)/2, -h k/2; -h k/2, -W + h(g_u+k)/2] [d1; u1] = rhs
  const double a11 = W + 0.5 * h * (g_d + k), a12 = -0.5 * h * k;
  const double a21 = -0.5 * h * k, a22 = -W + 0.5 * h * (g_u + k);
  const double b1 = (W - 0.5 * h * (g_d + k)) * d0 + 0.5 * h * k * u0 + h * c.s_down;
  const double b2 = -(W + 0.5 * h * (g_u + k)) * u0 + 0.5 * h * k * d0 + h * c.s_up;
  const double det = a11 * a22 - a12 * a21;
  d1 = (b1 * a22 - a12 * b2) / det;
  u1 = (a11 * b2 - a21 * b1) / det;
}

// Marches the cells from the top, the return temperature fixed by where
// the brine turns.
BrineProfile solve(const std::vector<Cell>& cell, double W, double k, double supply) {
  const int cells = static_cast<int>(cell.size());
  BrineProfile p;
  p.supply = supply;
  p.depth.assign(cells + 1, 0.0);
  p.down.resize(cells + 1);
  p.up.resize(cells + 1);
  for (int i = 0; i < cells; ++i) p.depth[i + 1] = p.depth[i] + cell[i].length;
  auto march = [&](double return_temperature) {
    p.down[0] = supply;
    p.up[0] = return_temperature;
    for (int i = 0; i < cells; ++i) march_cell(cell[i], W, k, p.down[i], p.up[i], p.down[i + 1], p.up[i + 1]);
    return p.up[cells] - p.down[cells];  // zero where the brine turns
  };
  const double x0 = supply, x1 = supply + 1.0;
  const double r0 = march(x0), r1 = march(x1);
  march(x0 - r0 * (x1 - x0) / (r1 - r0));
  p.return_temperature = p.up[0];
  p.heat = W * (p.return_temperature - supply);
  p.draw.resize(cells);
  for (int i = 0; i < cells; ++i) {
    const double d = 0.5 * (p.down[i] + p.down[i + 1]), u = 0.5 * (p.up[i] + p.up[i + 1]);
    p.draw[i] = cell[i].s_down - cell[i].g_down * d + cell[i].s_up - cell[i].g_up * u;
  }
  return p;
}

}  // namespace

BrineProfile steady_brine(double length, int cells, const CoaxialResistances& r, double W, SupplyChannel supply_channel,
                          double supply, const std::function<double(double)>& wall_temperature) {
  const double g = 1.0 / r.ground, h = length / cells;
  const bool down = supply_channel == SupplyChannel::annulus;
  std::vector<Cell> cell(cells);
  for (int i = 0; i < cells; ++i) {
    const double s = g * wall_temperature((i + 0.5) * h);
    cell[i] = down ? Cell{h, g, 0.0, s, 0.0} : Cell{h, 0.0, g, 0.0, s};
  }
  return solve(cell, W, 1.0 / r.channels, supply);
}

BrineProfile brine_with_draw(double length, int cells, const CoaxialResistances& r, double W,
                             SupplyChannel supply_channel, double supply, const std::function<double(double)>& draw) {
  const double h = length / cells;
  const bool down = supply_channel == SupplyChannel::annulus;
  std::vector<Cell> cell(cells);
  for (int i = 0; i < cells; ++i) {
    const double q = draw((i + 0.5) * h);
    cell[i] = down ? Cell{h, 0.0, 0.0, q, 0.0} : Cell{h, 0.0, 0.0, 0.0, q};
  }
  return solve(cell, W, 1.0 / r.channels, supply);
}

}  // namespace frostwall::design
