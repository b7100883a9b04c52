// A project assembled for the solver: the particle scene (rectangle or
// shaft section), the SPH conduction model on it, and its integrator.
// The heat run (freezing/heat_run.hpp) drives it; tests drive it directly.
#pragma once

#include <chrono>
#include <memory>
#include <optional>

#include "geometry/rectangle.hpp"
#include "geometry/shaft_section.hpp"
#include "geometry/symmetry.hpp"
#include "project/project.hpp"
#include "sph/kernel.hpp"
#include "sph/smoothing_lengths.hpp"
#include "thermal/integrator.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::freezing {

// Regular samples of the time curves over a run (wall.csv, monitoring); no
// RKL2 step of a run is longer than one interval (run_project).
inline constexpr std::size_t time_series_points = 200;

struct Model {
  // When build_model began: a run's wall time counts from here.
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();
  std::unique_ptr<geometry::Scene> scene;
  const geometry::RectangleScene* rectangle = nullptr;  // plain geometries
  const geometry::ShaftScene* shaft = nullptr;          // shaft sections
  std::optional<geometry::CooledFace> face;             // rectangles: where fronts are measured from
  double spacing = 0.0;  // the finest spacing asked for, resolved once (resolved_spacing)
  std::unique_ptr<sph::Kernel> kernel;
  // Smoothing lengths: one (lattice) or one per particle (graded placement).
  sph::SmoothingLengths smoothing;
  double h = 0.0;  // the smallest smoothing length (it sets the explicit step)
  std::unique_ptr<thermal::ThermalModel> model;
  std::unique_ptr<thermal::Integrator> integrator;
  // A porous plate: the pore each free particle lies in (-1: the matrix);
  // empty without pores. Pore particles are thermal material 1 (water).
  std::vector<int> pore_of;
  // What the run should tell the user beside the loader's warnings (a film
  // in the transitional band); the summary lists them with the others.
  std::vector<std::string> warnings;

  const particles::ParticleSet<2>& particles() const { return scene->particles; }
};

// The spacing used when numerics.spacing is not given.
double default_spacing(const project::Project& p);
// numerics.spacing, else the default: the finest spacing of the run.
double resolved_spacing(const project::Project& p);
// The narrowest gap between two pipe walls of a layout, m (at least a pipe
// diameter: pipes that touch or overlap are the loader's concern).
double narrowest_gap(const project::ShaftSection& s);

using geometry::symmetry_wedge;

// Throws project::ProjectError when the project asks for what this version
// cannot run or the machine cannot hold (checked before any output is
// written and before any particle is placed).
Model build_model(const project::Project& p);
// Only the particle cloud of build_model (scene, spacing, smoothing
// lengths; no model or integrator), with the same checks.
Model build_cloud(const project::Project& p);
// build_model on a cloud already built for p's geometry (build_cloud or
// copy_cloud).
Model build_model(const project::Project& p, Model cloud);
// A copy of a shaft section's cloud for a run of the same geometry with
// other soil or temperatures: the far field at p's temperature.
Model copy_cloud(const Model& cloud, const project::Project& p);

}  // namespace frostwall::freezing
