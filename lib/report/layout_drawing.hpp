// The plan view of a shaft section for the report: the excavation, the
// freeze pipes to scale, the wedge that was simulated, the rays OA (through
// a pipe) and OB (halfway to the next), the sensors and a scale bar. Pipes
// carry their numbers; failed pipes are drawn open and crossed; an as-built
// plan draws the design positions faintly beneath.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/layout.hpp"
#include "project/project.hpp"
#include "report/wedge_symmetry.hpp"

namespace frostwall::report {

struct LayoutDrawing {
  const project::ShaftSection* section = nullptr;
  std::vector<geometry::Pipe2> pipes;         // failed ones drawn open and crossed
  std::vector<geometry::Pipe2> design_pipes;  // drawn faintly beneath (an as-built plan)
  bool numbers = true;                        // each pipe's number (survey, failed_pipes) beside it
  WedgeSymmetry wedge;                        // mirror_lines 0: the full circle was simulated
  double OA = 0.0, OB = 0.0;                  // rad
  // Instead of OA and OB, one ray where the wall is thinnest (rad).
  std::optional<double> thinnest_ray;
  std::vector<project::Sensor> sensors;
};

std::string layout_svg(const LayoutDrawing& drawing, int size = 440);

// A plain-geometry problem (verification strip): the rectangle and its sides.
std::string rectangle_svg(const project::Rectangle& rectangle, int width = 440);

}  // namespace frostwall::report
