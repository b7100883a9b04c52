// The mirror symmetry of a pipe layout about the shaft axis, found from the
// pipe positions alone. With M mirror lines the temperature field is mirror
// symmetric about each of them, so a wedge of pi/M between two neighbouring
// lines (adiabatic sides) carries the whole section. Rotational symmetry
// without mirrors is not used: its wedge sides would need periodic, not
// adiabatic, boundaries.
#pragma once

#include <numbers>
#include <string>
#include <vector>

#include "geometry/layout.hpp"

namespace frostwall::geometry {

struct Wedge {
  int mirror_count = 0;                 // M: mirror lines through the origin; 0 = no mirror symmetry
  double start_angle = 0.0;             // rad in [0, 2pi): the ray OA, the wedge's first side
  double angle = 2 * std::numbers::pi;  // rad: pi/M counter-clockwise from start_angle, or 2pi when M = 0
};

// 1e-6 of the largest pipe radius: far below any survey's precision, far
// above the round-off of pipes placed by cos/sin.
double default_symmetry_tolerance(const std::vector<Pipe2>& pipes);

// Angles in [0, pi), ascending, of the lines through the origin that map the
// pipe set onto itself: every reflected pipe lands within `tolerance` metres
// of a pipe (as many pipes near the image as near the original, so doubled
// pipes count). Empty when no pipe is off the axis (then every line would do).
std::vector<double> mirror_lines(const std::vector<Pipe2>& pipes, double tolerance);

// The wedge to simulate. It starts on the ray at `preferred_start_angle` (rad;
// the outer ring's start angle, so OA runs through a pipe) when that ray lies
// on a mirror line, else on the first mirror ray counter-clockwise from it,
// and runs counter-clockwise by pi/M. If the mirror lines found are not M
// lines spaced pi/M apart (a near-symmetric layout at the tolerance's edge)
// the result is the full circle, which is always correct.
Wedge find_symmetry_wedge(const std::vector<Pipe2>& pipes, double preferred_start_angle, double tolerance);
Wedge find_symmetry_wedge(const std::vector<Pipe2>& pipes, double preferred_start_angle);

// The wedge that survives a regional groundwater flow along `flow_angle`
// (rad): the flow is mirror symmetric only about lines along it, so the
// half plane from the mirror ray nearest the flow's direction when the
// layout has a mirror line along the flow (M = 1, pi wide), else the full
// circle. `note` says which and why, for the log.
Wedge find_flow_symmetry_wedge(const std::vector<Pipe2>& pipes, double flow_angle, double tolerance, std::string& note);

// One line for the log: "symmetry: 26 mirror lines, wedge of 6.923 deg from 0.000 deg".
std::string describe(const Wedge& wedge);

// The smallest mirror-symmetric wedge of a shaft section's pipe layout, its
// first side through the layout's first pipe (OA). Layout problems must be
// checked first (layout_problems).
Wedge symmetry_wedge(const project::ShaftSection& section);

}  // namespace frostwall::geometry
