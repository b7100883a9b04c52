// The volume of a sphere (a grain) from its diameter.
#pragma once

#include <numbers>

namespace frostwall::particles {

// pi d^3 / 6 (m^3 for d in m). From a radius r: of 2 r, which is exactly
// 4/3 pi r^3 as that is written, (4/3) pi rounding to 8 (pi/6).
constexpr double sphere_volume_of_diameter(double d) { return std::numbers::pi / 6.0 * d * d * d; }

}  // namespace frostwall::particles
