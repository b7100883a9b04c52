#include "cfd_dem/surface_map.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mpi.h>

namespace frostwall::cfd_dem {

HeightMap height_map(const project::CfdDem& c, const dem::LammpsSession& lammps) {
  HeightMap m;
  m.cell = c.grains.diameter_max;
  m.x0 = c.box.low[0], m.y0 = c.box.low[1];
  m.nx = std::max(1, static_cast<int>(std::floor((c.box.high[0] - c.box.low[0]) / m.cell)));
  m.ny = std::max(1, static_cast<int>(std::floor((c.box.high[1] - c.box.low[1]) / m.cell)));
  m.cell = (c.box.high[0] - c.box.low[0]) / m.nx;  // whole columns; y's width follows x's
  m.ny = std::max(1, static_cast<int>(std::lround((c.box.high[1] - c.box.low[1]) / m.cell)));
  m.top.assign(static_cast<std::size_t>(m.nx) * m.ny, c.box.low[2]);
  const int n = lammps.local_count();
  double** x = lammps.position();
  const double* r = lammps.radius();
  for (int k = 0; k < n; ++k) {
    const int i = std::clamp(static_cast<int>((x[k][0] - m.x0) / m.cell), 0, m.nx - 1);
    const int j = std::clamp(static_cast<int>((x[k][1] - m.y0) / m.cell), 0, m.ny - 1);
    double& t = m.top[static_cast<std::size_t>(i + m.nx * j)];
    t = std::max(t, x[k][2] + r[k]);
  }
  if (lammps.ranks() > 1)
    MPI_Allreduce(MPI_IN_PLACE, m.top.data(), static_cast<int>(m.top.size()), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return m;
}

namespace {

// The three lines of columns nearest `at` (clamped inside 0..count-1).
std::array<int, 3> nearest_three(double at, double origin, double cell, int count) {
  const int mid = std::clamp(static_cast<int>(std::floor((at - origin) / cell)), 1, std::max(1, count - 2));
  return {std::max(0, mid - 1), mid, std::min(count - 1, mid + 1)};
}

// Along x (rows j nearest `at`) or along y (columns i nearest `at`).
Profile profile_along(const HeightMap& m, bool along_x, double at, const std::function<double(int, int)>& value) {
  Profile p;
  const auto across = along_x ? nearest_three(at, m.y0, m.cell, m.ny) : nearest_three(at, m.x0, m.cell, m.nx);
  const int count = along_x ? m.nx : m.ny;
  for (int k = 0; k < count; ++k) {
    double sum = 0.0;
    for (int a : across) sum += along_x ? value(k, a) : value(a, k);
    p.x.push_back((along_x ? m.x0 : m.y0) + (k + 0.5) * m.cell);
    p.f.push_back(sum / 3.0);
  }
  return p;
}

}  // namespace

Profile profile_along_x(const HeightMap& m, double y, const std::function<double(int, int)>& value) {
  return profile_along(m, true, y, value);
}

Profile profile_along_y(const HeightMap& m, double x, const std::function<double(int, int)>& value) {
  return profile_along(m, false, x, value);
}

Crater crater(const HeightMap& initial, const HeightMap& now, double y, double grain) {
  Crater c;
  auto settlement = [&](int i, int j) { return initial.at(i, j) - now.at(i, j); };
  const Profile p = profile_along_x(now, y, settlement);
  c.along_x = post::bump_flanks(p.x, p.f);
  for (int j = 0; j < now.ny; ++j)
    for (int i = 0; i < now.nx; ++i)
      if (const double s = settlement(i, j); s > 0.5 * grain) c.volume += s * now.cell * now.cell;
  return c;
}

std::optional<double> Heap::angle_deg() const {
  double sum = 0.0;
  int count = 0;
  for (const auto* b : {&along_x, &along_y})
    for (const auto& f : {b->low_side, b->high_side})
      if (f) sum += f->slope_deg, ++count;
  if (count == 0) return std::nullopt;
  return sum / count;
}

Heap heap(const HeightMap& now, double floor, double x, double y) {
  Heap h;
  auto height = [&](int i, int j) { return now.at(i, j) - floor; };
  const Profile px = profile_along_x(now, y, height);
  const Profile py = profile_along_y(now, x, height);
  h.along_x = post::bump_flanks(px.x, px.f);
  h.along_y = post::bump_flanks(py.x, py.f);
  return h;
}

}  // namespace frostwall::cfd_dem
