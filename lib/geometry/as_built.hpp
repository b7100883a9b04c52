// The shaft as built at a depth: the pipes where the survey puts them, the
// largest gap on each ring, the depths worth a section, and what in a
// survey no section can be built from (pipes that cross, sections below
// every pipe).
#pragma once

#include <string>
#include <vector>

#include "geometry/layout.hpp"
#include "geometry/survey.hpp"
#include "project/project.hpp"

namespace frostwall::geometry {

// The pipes at vertical depth z: design order and numbers, as-built
// centres, failed ones flagged; pipes that end above z are left out.
std::vector<Pipe2> pipes_at(const std::vector<PipeTrace>& traces, const std::vector<Pipe2>& design, double z);

// The widest opening between neighbouring working pipes of one ring, wall
// to wall (centre distance minus the diameter). Neighbours follow the
// ring's order (a measured layout, ring -1, by angle), skipping failed
// pipes, so a failed pipe's gap spans it.
struct RingGap {
  int ring = 0;
  double gap = 0.0;         // m
  int from = 0, to = 0;     // pipe numbers either side
  double x = 0.0, y = 0.0;  // its middle
};
std::vector<RingGap> largest_gaps(const std::vector<Pipe2>& pipes, double diameter);
// The widest of them (0 when no ring has two working pipes).
double largest_gap(const std::vector<Pipe2>& pipes, double diameter);

// The depth range each layer answers for: from halfway to the layer above
// (0 for the first) to halfway to the one below (the deepest pipe's bottom
// for the last); layers in the order given. Without layers, one range over
// the whole shaft.
struct DepthRange {
  double top = 0.0, bottom = 0.0;
  int layer = -1;  // index into project.layers; -1 without layers
};
std::vector<DepthRange> layer_ranges(const project::Project& p, double deepest);

// The section depths, ascending and at least 0.1 m apart: as given, every
// sections.every metres, or every layer's depth (without layers
// design.depth, else mid-shaft) and the depth of the largest gap in each
// layer's range.
std::vector<double> section_depths(const project::Project& p, const std::vector<PipeTrace>& traces,
                                   const std::vector<Pipe2>& design);

// Problems of an as-built project, one line each naming the JSON path (and
// the survey file's line): pipes whose centres come closer than one
// diameter, section depths below every pipe.
std::vector<std::string> as_built_problems(const project::Project& p, const std::vector<PipeTrace>& traces,
                                           const std::vector<Pipe2>& design);

}  // namespace frostwall::geometry
