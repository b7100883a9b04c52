#include "cfd_dem/soil.hpp"

#include <algorithm>
#include <cmath>
#include <mpi.h>
#include <numbers>

#include "particles/sphere.hpp"

namespace frostwall::cfd_dem {

namespace {

constexpr int heights = 8;  // height bins over the cavity's centre for the moved zones' boundaries

void sum_all(const dem::LammpsSession& l, double* data, int n) {
  if (l.ranks() > 1) MPI_Allreduce(MPI_IN_PLACE, data, n, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

void max_all(const dem::LammpsSession& l, double* data, int n) {
  if (l.ranks() > 1) MPI_Allreduce(MPI_IN_PLACE, data, n, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

// A moved zone's boundary: its reach from the cavity's axis in height bins
// from the cavity's centre to the top, a straight line fitted to reach
// against height; the angle of that line from the horizontal (three bins
// at least).
std::optional<double> boundary_angle(const std::array<double, heights>& reach, double z0, double top) {
  double sz = 0, sr = 0, szz = 0, szr = 0, count = 0;
  for (int b = 0; b < heights; ++b) {
    if (reach[b] <= 0.0) continue;
    const double z = z0 + (b + 0.5) * (top - z0) / heights;
    sz += z, sr += reach[b], szz += z * z, szr += z * reach[b], count += 1;
  }
  if (count < 3) return std::nullopt;
  const double slope = (count * szr - sz * sr) / (count * szz - sz * sz);  // dr/dz
  return std::atan2(1.0, std::abs(slope)) * 180.0 / std::numbers::pi;
}

}  // namespace

SoilWatch::SoilWatch(const project::CfdDem& c, const dem::LammpsSession& lammps) : c_(c), lammps_(lammps) {
  // Surface bins of two grain diameters along x.
  const double length = c.box.high[0] - c.box.low[0];
  const int bins = std::max(1, static_cast<int>(length / (2.0 * c.grains.diameter_max)));
  bin_width_ = length / bins;
  for (int b = 0; b < bins; ++b) bin_centres_.push_back(c.box.low[0] + (b + 0.5) * bin_width_);
  initial_surface_ = surface();
  initial_map_ = height_map(c, lammps);
  // Where every grain starts, on every rank (ids index it).
  const int n = lammps.local_count();
  const int* ids = lammps.ids();
  double** x = lammps.position();
  std::vector<double> mine;
  for (int i = 0; i < n; ++i) mine.insert(mine.end(), {double(ids[i]), x[i][0], x[i][1], x[i][2]});
  int size = static_cast<int>(mine.size());
  std::vector<int> sizes(lammps.ranks()), offsets(lammps.ranks());
  MPI_Allgather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int k = 1; k < lammps.ranks(); ++k) offsets[k] = offsets[k - 1] + sizes[k - 1];
  std::vector<double> all(offsets.back() + sizes.back());
  MPI_Allgatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  for (std::size_t k = 0; k + 3 < all.size(); k += 4) {
    const auto id = static_cast<std::size_t>(all[k]);
    if (start_.size() <= id) start_.resize(id + 1, {NAN, NAN, NAN});
    start_[id] = {all[k + 1], all[k + 2], all[k + 3]};
  }
}

// The highest grain top in each bin of the strip two grain diameters
// either side of the line through the cavity (or the box's middle) along x.
std::vector<double> SoilWatch::surface() const {
  const double y0 = c_.cavity ? c_.cavity->centre[1] : 0.5 * (c_.box.low[1] + c_.box.high[1]);
  std::vector<double> top(bin_centres_.size(), c_.box.low[2]);
  const int n = lammps_.local_count();
  double** x = lammps_.position();
  const double* r = lammps_.radius();
  for (int i = 0; i < n; ++i) {
    if (std::abs(x[i][1] - y0) > 2.0 * c_.grains.diameter_max) continue;
    const int b = std::clamp(static_cast<int>((x[i][0] - c_.box.low[0]) / bin_width_), 0, int(top.size()) - 1);
    top[b] = std::max(top[b], x[i][2] + r[i]);
  }
  max_all(lammps_, top.data(), static_cast<int>(top.size()));
  return top;
}

SoilMeasures SoilWatch::measure(const CfdDemCoupling& coupling) const {
  SoilMeasures m;
  const auto& grid = coupling.grid();
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  double** x = lammps_.position();
  const double* r = lammps_.radius();
  const double d = c_.grains.diameter_max;
  // Point A's cell.
  const int cell_a =
      c_.point_a ? grid.shape().cell_of(pore_water::Vec3(c_.point_a->at(0), c_.point_a->at(1), c_.point_a->at(2))) : -1;
  auto cell_of = [&](const double* p) { return grid.shape().cell_of(pore_water::Vec3(p[0], p[1], p[2])); };
  // Local sums: zone solid volume, grains in A's cell and their forces, displaced grains.
  std::array<double, 4 + 9> sums{};
  std::array<double, heights> reach{}, reach_moved{};
  const double top = c_.box.high[2];
  const double z0 = c_.cavity ? c_.cavity->centre[2] : c_.box.low[2];
  for (int i = 0; i < n; ++i) {
    if (c_.cavity) {
      const double dx = x[i][0] - c_.cavity->centre[0], dy = x[i][1] - c_.cavity->centre[1];
      const double rho = std::hypot(dx, dy);
      if (rho < c_.cavity->radius && x[i][2] > c_.cavity->centre[2] + c_.cavity->radius)
        sums[0] += particles::sphere_volume_of_diameter(2.0 * r[i]);
    }
    if (cell_a >= 0 && cell_of(x[i]) == cell_a) {
      sums[1] += 1.0;
      const auto& f = coupling.force_by_kind(ids[i]);
      for (int kind = 0; kind < 3; ++kind)
        for (int k = 0; k < 3; ++k) sums[3 + 3 * kind + k] += f[kind][k];
    }
    if (static_cast<std::size_t>(ids[i]) < start_.size()) {
      const auto& s = start_[ids[i]];
      const double moved = std::hypot(x[i][0] - s[0], x[i][1] - s[1], x[i][2] - s[2]);
      if (moved > d) {
        sums[12] += 1.0;
        if (c_.cavity && x[i][2] > z0) {
          const int b = std::min(heights - 1, static_cast<int>((x[i][2] - z0) / (top - z0) * heights));
          reach_moved[b] =
              std::max(reach_moved[b], std::hypot(x[i][0] - c_.cavity->centre[0], x[i][1] - c_.cavity->centre[1]));
        }
      }
      if (moved > 2.0 * d) {
        sums[2] += 1.0;
        if (c_.cavity && x[i][2] > z0) {
          const int b = std::min(heights - 1, static_cast<int>((x[i][2] - z0) / (top - z0) * heights));
          reach[b] = std::max(reach[b], std::hypot(x[i][0] - c_.cavity->centre[0], x[i][1] - c_.cavity->centre[1]));
        }
      }
    }
  }
  sum_all(lammps_, sums.data(), static_cast<int>(sums.size()));
  max_all(lammps_, reach.data(), heights);
  max_all(lammps_, reach_moved.data(), heights);
  if (c_.cavity) {
    // The zone reaches the surface as the run started, over the cavity.
    const int b = std::clamp(static_cast<int>((c_.cavity->centre[0] - c_.box.low[0]) / bin_width_), 0,
                             int(initial_surface_.size()) - 1);
    const double length = initial_surface_[b] - (c_.cavity->centre[2] + c_.cavity->radius);
    const double zone = std::numbers::pi * c_.cavity->radius * c_.cavity->radius * length;
    if (zone > 0.0) m.zone_porosity = 1.0 - sums[0] / zone;
  }
  if (cell_a >= 0) {
    if (c_.flow) m.pressure_drop_a = grid.face_pressure(static_cast<int>(c_.flow->inflow)) - grid.pressure()[cell_a];
    m.grains_a = sums[1];
    for (int kind = 0; kind < 3; ++kind)
      for (int k = 0; k < 3; ++k) m.mean_force_a[kind][k] = sums[1] > 0 ? sums[3 + 3 * kind + k] / sums[1] : 0.0;
  }
  m.displaced = sums[2];
  m.moved = sums[12];
  m.cone_angle = boundary_angle(reach, z0, top);
  m.slip_angle = boundary_angle(reach_moved, z0, top);
  const HeightMap now = height_map(c_, lammps_);
  if (c_.cavity) m.crater = crater(initial_map_, now, c_.cavity->centre[1], d);
  if (c_.heap) m.heap = heap(now, c_.box.low[2], c_.heap->axis[0], c_.heap->axis[1]);
  // The surface's settlement.
  m.surface = surface();
  int first = -1, last = -1;
  for (std::size_t b = 0; b < m.surface.size(); ++b) {
    const double s = initial_surface_[b] - m.surface[b];
    m.settlement_max = std::max(m.settlement_max, s);
    if (s > d) {
      if (first < 0) first = int(b);
      last = int(b);
    }
  }
  if (first >= 0) m.settlement_width = (last - first + 1) * bin_width_;
  return m;
}

}  // namespace frostwall::cfd_dem
