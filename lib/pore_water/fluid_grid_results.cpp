// The fluid grid's results: velocities at the centres, values at a grain,
// the flow balance and the faces' pressures.
#include <algorithm>
#include <cmath>

#include "pore_water/fluid_grid.hpp"
#include "pore_water/grid_indexing.hpp"

namespace frostwall::pore_water {

using namespace grid;

// U = J - (1 - eps) v_p: the mixture flux J (mean of the opposite faces')
// less the grains' own volume flux in the cell. (The faces' slip plus
// eps v_p would mix the faces' grain velocity, averaged with grain-free
// neighbours, into the cell's: a lone settling grain would drag the water
// down with it at half its speed.)
Vec3 FluidGrid::centre_velocity(int c) const {
  return face_mean(shape_, slip_, c) + face_mean(shape_, grain_, c) - (1.0 - porosity_[c]) * grain_velocity_[c];
}

std::vector<Vec3> FluidGrid::superficial_velocity() const {
  std::vector<Vec3> U(shape_.count());
  for (int c = 0; c < shape_.count(); ++c) U[c] = centre_velocity(c);
  return U;
}

FluidSample FluidGrid::sample(const Vec3& x) const {
  std::array<int, 3> i0;
  std::array<double, 3> f;
  for (int a = 0; a < 3; ++a) {
    const int n = shape_.cells[a];
    const double s = std::clamp((x[a] - shape_.low[a]) / shape_.cell_size(a) - 0.5, 0.0, double(n - 1));
    i0[a] = std::min(int(std::floor(s)), std::max(n - 2, 0));
    f[a] = s - i0[a];
  }
  FluidSample out;
  out.porosity = 0.0;
  for (int u = 0; u < 2; ++u)
    for (int v = 0; v < 2; ++v)
      for (int w = 0; w < 2; ++w) {
        const double weight = (u ? f[0] : 1.0 - f[0]) * (v ? f[1] : 1.0 - f[1]) * (w ? f[2] : 1.0 - f[2]);
        if (weight == 0.0) continue;
        const int c = shape_.index(i0[0] + u, i0[1] + v, i0[2] + w);
        const Vec3 U = centre_velocity(c);
        out.porosity += weight * porosity_[c];
        out.superficial_velocity += weight * U;
        out.fluid_velocity += weight * U / porosity_[c];
        out.pressure_gradient += weight * face_mean(shape_, gradient_, c);
        if (!drag_coefficient_.empty()) {
          out.drag_coefficient += weight * drag_coefficient_[c];
          out.drag_velocity += weight * drag_coefficient_[c] * U / porosity_[c];
        }
      }
  if (out.drag_coefficient > 0.0) out.drag_velocity /= out.drag_coefficient;
  return out;
}

double FluidGrid::cell_outflow(int c) const {
  const Cell p = coords(shape_, c);
  double out = 0.0;
  for (int a = 0; a < 3; ++a) {
    const int lo = face_id(shape_, a, p), hi = face_id(shape_, a, p, 1);
    out += shape_.face_area(a) * (slip_[a][hi] + grain_[a][hi] - slip_[a][lo] - grain_[a][lo]);
  }
  return out;
}

double FluidGrid::inflow() const {
  double q = 0.0;
  for (int face = 0; face < 6; ++face)
    if (faces_[face].kind == FaceKind::inflow_velocity) {
      const int a = face / 2;
      q += faces_[face].value * (shape_.high[(a + 1) % 3] - shape_.low[(a + 1) % 3]) *
           (shape_.high[(a + 2) % 3] - shape_.low[(a + 2) % 3]);
    }
  return q;
}

// Net outward flow through the pressure faces; grains never cross a box
// face, so the mixture's is the slip flux.
double FluidGrid::outflow() const {
  double q = 0.0;
  for (int c = 0; c < shape_.count(); ++c) {
    const Cell p = coords(shape_, c);
    for (int a = 0; a < 3; ++a)
      for (int side = 0; side < 2; ++side)
        if (faces_[2 * a + side].kind == FaceKind::pressure && p[a] == (side == 0 ? 0 : shape_.cells[a] - 1))
          q += (side == 0 ? -1.0 : 1.0) * shape_.face_area(a) * slip_[a][face_id(shape_, a, p, side)];
  }
  return q;
}

double FluidGrid::largest_cell_imbalance() const {
  double worst = 0.0;
  for (int c = 0; c < shape_.count(); ++c) worst = std::max(worst, std::abs(cell_outflow(c)));
  return worst;
}

double FluidGrid::face_pressure(int face) const {
  if (face < 0 || face > 5) throw std::invalid_argument("fluid grid: face index must be 0..5");
  if (faces_[face].kind == FaceKind::pressure) return faces_[face].value;
  const int a = face / 2, side = face % 2;
  const double half = (side == 0 ? -0.5 : 0.5) * shape_.cell_size(a);
  // Every face cell has the same area: the area-weighted mean is the mean.
  double sum = 0.0;
  int count = 0;
  for (int c = 0; c < shape_.count(); ++c) {
    const Cell p = coords(shape_, c);
    if (p[a] != (side == 0 ? 0 : shape_.cells[a] - 1)) continue;
    sum += pressure_[c] + half * gradient_[a][face_id(shape_, a, p, side)];
    ++count;
  }
  return sum / count;
}

}  // namespace frostwall::pore_water
