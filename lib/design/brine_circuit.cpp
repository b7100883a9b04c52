#include "design/brine_circuit.hpp"

namespace frostwall::design {

namespace {

struct Cell {
  double length, wall;  // m, degC
};

// One cell's two balances solved for its lower face's temperatures from its
// upper face's (d0, u0).
void march_cell(const Cell& c, double W, double g_d, double g_u, double k, double d0, double u0, double& d1,
                double& u1) {
  const double h = c.length;
  // [W + h(g_d+k)/2, -h k/2; -h k/2, -W + h(g_u+k)/2] [d1; u1] = rhs
  const double a11 = W + 0.5 * h * (g_d + k), a12 = -0.5 * h * k;
  const double a21 = -0.5 * h * k, a22 = -W + 0.5 * h * (g_u + k);
  const double b1 = (W - 0.5 * h * (g_d + k)) * d0 + 0.5 * h * k * u0 + h * g_d * c.wall;
  const double b2 = -(W + 0.5 * h * (g_u + k)) * u0 + 0.5 * h * k * d0 + h * g_u * c.wall;
  const double det = a11 * a22 - a12 * a21;
  d1 = (b1 * a22 - a12 * b2) / det;
  u1 = (a11 * b2 - a21 * b1) / det;
}

}  // namespace

BrineProfile steady_brine(double length, int cells, const CoaxialResistances& r, double W, SupplyChannel supply_channel,
                          double supply, const std::function<double(double)>& wall_temperature) {
  const double g = 1.0 / r.ground, k = 1.0 / r.channels;
  const double g_d = supply_channel == SupplyChannel::annulus ? g : 0.0, g_u = g - g_d;
  std::vector<Cell> cell(cells);
  const double h = length / cells;
  for (int i = 0; i < cells; ++i) cell[i] = {h, wall_temperature((i + 0.5) * h)};

  BrineProfile p;
  p.supply = supply;
  p.depth.resize(cells + 1);
  p.down.resize(cells + 1);
  p.up.resize(cells + 1);
  auto march = [&](double return_temperature) {
    p.down[0] = supply;
    p.up[0] = return_temperature;
    for (int i = 0; i < cells; ++i) {
      p.depth[i + 1] = (i + 1) * h;
      march_cell(cell[i], W, g_d, g_u, k, p.down[i], p.up[i], p.down[i + 1], p.up[i + 1]);
    }
    return p.up[cells] - p.down[cells];  // zero where the brine turns
  };
  const double x0 = supply, x1 = supply + 1.0;
  const double r0 = march(x0), r1 = march(x1);
  march(x0 - r0 * (x1 - x0) / (r1 - r0));

  const auto& annulus = p.annulus(supply_channel);
  p.draw.resize(cells);
  for (int i = 0; i < cells; ++i) p.draw[i] = g * (cell[i].wall - 0.5 * (annulus[i] + annulus[i + 1]));
  p.return_temperature = p.up[0];
  p.heat = W * (p.return_temperature - supply);
  return p;
}

}  // namespace frostwall::design
