// The ground's surface as a height map: columns one grain diameter square
// over the box's floor, each holding the top of its highest grain (the
// floor where it has none). From two maps, a crater: the settlement along x
// through a point, its flanks and the trough's volume; from one, a heap:
// its height along x and y through its axis and the flanks' slope.
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "dem/lammps_session.hpp"
#include "post/flank.hpp"
#include "project/cfd_dem.hpp"

namespace frostwall::cfd_dem {

struct HeightMap {
  double x0 = 0.0, y0 = 0.0, cell = 0.0;  // the first column's low corner, the column width (m)
  int nx = 0, ny = 0;
  std::vector<double> top;  // m, column (i, j) at i + nx j
  double at(int i, int j) const { return top[static_cast<std::size_t>(i + nx * j)]; }
};

// Collective: every rank's grains.
HeightMap height_map(const project::CfdDem& c, const dem::LammpsSession& lammps);

// A profile through the map: `value(i, j)` averaged over the three rows
// (along x) or columns (along y) nearest the line at `at`.
struct Profile {
  std::vector<double> x, f;
};
Profile profile_along_x(const HeightMap& m, double y, const std::function<double(int, int)>& value);
Profile profile_along_y(const HeightMap& m, double x, const std::function<double(int, int)>& value);

struct Crater {
  post::Bump along_x;   // the settlement along x through the cavity's axis
  double volume = 0.0;  // m3: the settlement summed over columns that sank by more than half a grain
};
Crater crater(const HeightMap& initial, const HeightMap& now, double y, double grain);

struct Heap {
  post::Bump along_x, along_y;              // the height above the floor through the axis
  std::optional<double> angle_deg() const;  // the mean slope of the flanks found
};
Heap heap(const HeightMap& now, double floor, double x, double y);

}  // namespace frostwall::cfd_dem
