// Where the freeze pipes of a shaft section are, and what is wrong with a
// layout that a solver cannot or should not model (pipes on top of each
// other, in the excavation, or outside or too near the far field).
#pragma once

#include <string>
#include <vector>

#include "project/project.hpp"

namespace frostwall::geometry {

// One pipe centre in the section plane (metres, shaft axis at the origin).
struct Pipe2 {
  double x = 0.0, y = 0.0;
  // The ring it belongs to: single, three-hole, four-hole: 0 outer, 1 inner;
  // rings: index into layout.rings; pipes (measured): -1, no ring.
  int ring = 0;
  int index = 0;      // within its ring (pipe 0 at the ring's start angle), or into layout.pipes
  std::string label;  // "outer 3", "inner 5", "ring 1 pipe 4", "pipe 2" (indices from 0, as in the JSON)
  int number = 0;     // from 1, in this order over the whole layout: what a survey and failed_pipes use
  bool failed = false;
};

// Every pipe centre of the layout, ring by ring (outer before inner), each
// ring counter-clockwise from its first pipe. Rings with a count below 1 or
// a missing inner radius (already reported by the loader) give no pipes.
// Failed pipes are left out: they are ground like the rest.
std::vector<Pipe2> pipe_positions(const project::Layout& layout);
// The same with the failed pipes, marked (drawings, the survey's numbering).
std::vector<Pipe2> all_pipe_positions(const project::Layout& layout);

// The disc model needs this much soil, in pipe diameters, between a pipe's
// wall and the far-field circle, so the fixed far field does not sit in the
// pipe's own cooling zone.
inline constexpr double far_field_clearance_diameters = 2.0;

// Input errors of the section's geometry, one line each in the form
// "<json.path>: <problem>", in a fixed order: pipes overlapping pipes,
// pipes reaching into the excavation, then the far field (too small, or for
// the disc model too close). Empty when the layout is usable. Each line
// names what the user should change: a ring (or measured pipe) for overlaps
// and the excavation, domain.outer_radius for the far field.
std::vector<std::string> layout_problems(const project::ShaftSection& section);

}  // namespace frostwall::geometry
