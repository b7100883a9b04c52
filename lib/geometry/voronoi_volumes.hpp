// Particle volumes from Voronoi cells. A lattice particle's volume is its
// lattice cell, but near a mirror plane that the lattice does not follow,
// or next to the rings of a pipe, the cells overlap or leave gaps. The
// Voronoi cell of each free particle, computed with its mirror images and
// the fixed particles around it (CGAL's Delaunay triangulation, dual
// cells), is exactly the share of the plane that particle stands for: on a
// lattice it is the lattice cell, at a mirror plane it ends at the plane.
#pragma once

#include "particles/particle_set.hpp"

namespace frostwall::geometry {

// Sets the volume of every free particle to its Voronoi cell area (2-D).
// `reach` is the kernel support (the mirror images that matter lie within).
// Fixed particles keep their volumes.
void assign_voronoi_volumes(particles::ParticleSet<2>& particles, double reach);

}  // namespace frostwall::geometry
