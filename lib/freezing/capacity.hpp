// What a project will cost before any of it is built: the particle count
// from the spacing the placement asks for (the graded size field or the
// lattice spacing) over the simulated region, and the memory that takes.
// A project above the limit is refused with one line naming the field to
// change and a value that fits (project-format.md: a project the machine
// cannot hold is refused before any work), instead of hanging for minutes
// in the placement of billions of particles.
#pragma once

#include <cstddef>
#include <string>

#include "project/project.hpp"

namespace frostwall::freezing {

// Peak memory of a run per free particle, measured (bench/README.md): the
// neighbour pairs, the moment system, the triangulations of the closure and
// front detectors and the VTK frames. Used to turn memory into particles.
inline constexpr double bytes_per_particle = 20000.0;

struct CapacityEstimate {
  double particles = 0.0;  // free particles, estimated
  double limit = 0.0;      // numerics.max_particles, or from the machine's memory
  bool fits() const { return particles <= limit; }
};

// The default limit: half the machine's physical memory over bytes_per_particle.
double default_particle_limit();

// spacing: the finest spacing the run uses (freezing/model.hpp resolves it).
CapacityEstimate estimate_capacity(const project::Project& p, double spacing);

// Line-sink pipes: the narrowest gap between two pipe walls holds at least
// this many spacings (closure is decided there).
inline constexpr double min_rows_in_gap = 4.0;

// Throws project::ProjectError naming numerics.spacing or domain.outer_radius
// (or the rectangle's size) when the estimate is over the limit, or when a
// line-sink cloud is too coarse for the gap between two pipes.
void check_capacity(const project::Project& p, double spacing);

}  // namespace frostwall::freezing
