// The particle scene of a horizontal shaft section: the smallest mirror-
// symmetric wedge of the layout (apex on the shaft axis, far-field arc at
// domain.outer_radius) minus the pipe discs.
//  - Free particles sit on a square lattice aligned with the wedge's second
//    side (OB, the interface plane, where the wall is thinnest), rows half a
//    spacing off it, so OB's mirror images continue the lattice exactly.
//  - Each pipe disc holds ceil(2h/spacing) rings of fixed particles that
//    follow its circle, the outer one on the pipe wall (the paper's point
//    pipe, "pipe": {"model": "point"}, is a single fixed particle; so is a
//    line sink, "line", whose ground begins at the wall: pipes/ holds how
//    each model meets the ground).
//  - Beyond the far-field arc, the same number of lattice layers hold the
//    far-field temperature (none when the far field is adiabatic).
//  - The wedge sides are mirror planes; pipes they cut are kept on the
//    wedge side only, and the mirror supplies the rest.
// Which side of a wedge side or a circle a point lies on is decided with
// CGAL's exact predicates, so particles near a plane are classified the
// same way every time.
#pragma once

#include <vector>

#include "geometry/layout.hpp"
#include "geometry/scene.hpp"
#include "geometry/size_field.hpp"
#include "geometry/symmetry.hpp"
#include "project/project.hpp"

namespace frostwall::geometry {

struct ShaftScene : Scene {
  Wedge wedge;
  std::vector<Pipe2> pipes;  // every pipe of the layout (not only the wedge's)
  double far_field_radius = 0.0;
  double pipe_radius = 0.0;
  int pipe_boundary = -1;       // boundary id of the pipes
  int far_field_boundary = -1;  // boundary id of the far field, -1 if adiabatic
};

ShaftScene build_shaft_section(const project::ShaftSection& section, const project::Domain& domain, const Wedge& wedge,
                               double spacing, double h);

// The spacing a graded shaft section asks for (numerics.placement "graded"):
//  - `finest` at every pipe wall, growing at (growth - 1) per metre away;
//  - band_coarsening * finest in the wall band, the annulus from
//    band_width inside the innermost pipe ring to band_width outside the
//    outermost, growing the same way outside it;
//  - at most coarsening * finest;
//  - near a wedge's apex at most the arc between the wedge's mirror images
//    (r * angle), so the images around the axis still form round cells.
SizeField shaft_size_field(const project::ShaftSection& section, const Wedge& wedge, double finest,
                           const project::Grading& grading);

// The same scene on a graded cloud (graded_placement.hpp): free particles
// from a CVT of the wedge; each pipe disc holds ceil(2h/s) rings of fixed
// particles at the pipe's spacing s, as on the lattice; the far field is
// held by the free particles' reflections across the far-field circle
// (within 2.2 h of it), each the antisymmetric image of its source. Free
// particles take Voronoi volumes; every particle carries its local spacing.
ShaftScene build_graded_shaft_section(const project::ShaftSection& section, const project::Domain& domain,
                                      const Wedge& wedge, const SizeField& size, double smoothing_ratio);

// The whole ring made of the wedge's particles: every particle copied by
// every element of the wedge's mirror group, the mirror planes dropped.
// The copies carry the wedge's volumes, so a run on it differs from the
// wedge's only in how the symmetry planes are handled (a check of them).
void unfold_to_full_ring(ShaftScene& scene);

// True when p lies strictly inside the wedge (sides excluded).
bool inside_wedge(const Wedge& wedge, const particles::Vec<2>& p);

}  // namespace frostwall::geometry
