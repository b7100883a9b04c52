// A plain-geometry problem (rectangle) assembled from its project: the
// particle scene, the SPH conduction model on it, and its integrator.
// run_project drives it; tests drive it directly.
#pragma once

#include <memory>
#include <optional>

#include "geometry/rectangle.hpp"
#include "project/project.hpp"
#include "sph/kernel.hpp"
#include "thermal/integrator.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::run {

struct PlainModel {
  geometry::RectangleScene scene;
  std::optional<geometry::CooledFace> face;
  std::unique_ptr<sph::Kernel> kernel;
  double h = 0.0;
  std::unique_ptr<thermal::ThermalModel> model;
  std::unique_ptr<thermal::Integrator> integrator;
};

// Throws project::ProjectError when the project asks for what this version
// cannot run (it is checked before any output is written).
PlainModel build_plain_model(const project::Project& p);

}  // namespace frostwall::run
