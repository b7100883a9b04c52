// A borehole survey turned into pipe traces: each freeze pipe's centre as a
// polyline in 3-D (x, y in the layout's frame, z the vertical depth down).
//  - Positions (pipe,depth,x,y) are taken as they are, with the collar at
//    the design position at depth 0 when the file starts deeper.
//  - Stations (pipe,depth,inclination_deg,azimuth_deg), depth measured along
//    the hole, are desurveyed by the minimum-curvature method from the
//    collar at the design position: between two stations the hole is the
//    circular arc tangent to both directions, so
//      dogleg b = acos(t1 . t2),  RF = (2 / b) tan(b / 2)  (1 as b -> 0),
//      step = (dMD / 2) (t1 + t2) RF,
//    with t = (sin I sin A, sin I cos A, cos I) (azimuth clockwise from +y).
//    The stretch from the collar to the first station runs along the first
//    station's direction.
// Between trace points a position is interpolated linearly in depth; below
// the last, the trace goes on along its last segment.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "geometry/layout.hpp"
#include "project/as_built.hpp"

namespace frostwall::geometry {

struct TracePoint {
  double z = 0.0;  // vertical depth, m (down)
  double x = 0.0, y = 0.0;
  int line = 0;  // the survey file's line it came from (0: the collar)
};

struct PipeTrace {
  std::vector<TracePoint> points;  // by increasing z, the collar first
  double bottom = 0.0;             // vertical depth of the pipe's end
  // The centre at vertical depth z (above the bottom or not: the caller
  // decides whether the pipe reaches there).
  std::array<double, 2> at(double z) const;
};

// One trace per pipe of `design` (all_pipe_positions order, failed ones
// included); pipe_depth: every pipe's bottom, else its deepest point.
std::vector<PipeTrace> pipe_traces(const project::Survey& survey, const std::vector<Pipe2>& design);

// Minimum curvature from `start` (x, y, z) along measured-depth stations
// {md, inclination_deg, azimuth_deg}; returns the position at every station.
std::vector<std::array<double, 3>> minimum_curvature(std::array<double, 3> start,
                                                     const std::vector<std::array<double, 3>>& stations);

}  // namespace frostwall::geometry
