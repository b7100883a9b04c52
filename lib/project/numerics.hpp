// The "numerics" block: how the particle methods discretise a project
// (kernel, integrator, spacing, placement, PD horizon). Plain choices only;
// lib/sph and lib/thermal include this header and nothing else of the
// project.
#pragma once

#include <optional>

namespace frostwall::project {

enum class KernelKind { wendland_c2, cubic_spline };
enum class IntegratorKind { explicit_euler, implicit, rkl2 };
enum class ConductivityMean { harmonic, arithmetic };
enum class LaplacianForm { renormalised, plain };
enum class Placement { lattice, graded };
// The particle method of heat conduction: SPH pair weights or PD thermal bonds.
enum class Method { sph, pd };

// numerics.placement "graded": the spacing grows from numerics.spacing
// (finest, at the pipe walls) through a wall band to a coarse far field.
struct Grading {
  double coarsening = 8.0;       // coarsest spacing / finest
  double growth = 1.2;           // largest ratio of the spacings of neighbouring particles
  double band_coarsening = 1.0;  // spacing in the wall band / finest
  // Half-width of the wall band, m: beyond the innermost and outermost pipe
  // rings (shaft sections) or from the cooled face (rectangles). nullopt =
  // frostwall chooses (2 m round the rings; a third of a rectangle).
  std::optional<double> band_width;
};

struct Numerics {
  std::optional<double> spacing;  // m; nullopt = frostwall chooses
  KernelKind kernel = KernelKind::wendland_c2;
  double smoothing_ratio = 1.3;  // h / spacing
  IntegratorKind integrator = IntegratorKind::rkl2;
  double beta = 0.1;  // explicit step: dt = beta h^2 / alpha_max
  // RKL2 and implicit steps: the largest enthalpy change of a particle per
  // step, as a fraction of the latent heat (the step adapts to hold it).
  // Default 1 for RKL2, 0.25 for implicit (load_project).
  double step_change = 0.25;
  // Shaft sections with sensors: the largest error, K, of a sensor's
  // reading interpolated linearly in time between two steps; the step is
  // held to keep it (freezing/thermometers.hpp).
  double sensor_tolerance = 0.0002;
  ConductivityMean conductivity_mean = ConductivityMean::harmonic;
  LaplacianForm laplacian = LaplacianForm::renormalised;
  Method method = Method::sph;
  // PD horizon delta in spacings; 3.015 so that no neighbour sits exactly
  // on it (the Madenci & Oterkus book code's choice).
  double horizon = 3.015;
  // Shaft sections: simulate the smallest mirror-symmetric wedge ("auto"),
  // or the whole ring ("off": the wedge's particles mirrored round it; a
  // check of the wedge's planes), or the whole ring placed as a layout with
  // no symmetry is ("none": the cloud an as-built section gets).
  bool use_symmetry = true;
  bool unsymmetric_cloud = false;            // "none"
  Placement placement = Placement::lattice;  // default graded for shaft sections (load_project)
  Grading grading;
  // Refuse a project estimated to need more free particles than this
  // (nullopt: from the machine's memory, freezing/capacity.hpp).
  std::optional<double> max_particles;
  // true: after the run, three coarser runs (1.35, 1.5 and 1.65 times the
  // spacing) estimate the discretisation error of every headline number
  // (lib/run/error_estimate.hpp). Off by default (the twins take about as
  // long as the run: 0.91 of the main job's CPU time, bench/README.md);
  // `frostwall study` turns it on unless the project says false.
  bool error_estimate = false;
};

}  // namespace frostwall::project
