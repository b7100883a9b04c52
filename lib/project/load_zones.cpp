#include "project/load_zones.hpp"

#include <cmath>
#include <fmt/core.h>

namespace frostwall::project {

bool InitialZone::contains(double x, double y) const {
  switch (shape) {
    case Shape::rectangle: return x >= numbers[0] && x <= numbers[2] && y >= numbers[1] && y <= numbers[3];
    case Shape::circle: return std::hypot(x - numbers[0], y - numbers[1]) <= numbers[2];
    case Shape::polygon: {
      // Even-odd rule: a ray to +x crosses the outline an odd number of times.
      bool inside = false;
      for (std::size_t i = 0, j = corners.size() - 1; i < corners.size(); j = i++) {
        const auto &a = corners[i], &b = corners[j];
        if ((a[1] > y) != (b[1] > y) && x < a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1])) inside = !inside;
      }
      return inside;
    }
  }
  return false;
}

namespace detail {

namespace {

// n numbers, or a problem naming the path.
std::vector<double> read_numbers(const Node& n, std::size_t count, const char* form) {
  std::vector<double> out;
  if (n.array() != count) {
    n.problem(fmt::format("must be {}, got {}", form, n.shown()));
    return out;
  }
  for (std::size_t k = 0; k < count; ++k)
    if (const auto v = n[k].required().number()) out.push_back(*v);
  return out.size() == count ? out : std::vector<double>{};
}

InitialZone read_zone(const Node& n) {
  InitialZone zone;
  if (!n.object({"rectangle", "circle", "polygon", "temperature"})) return zone;
  zone.temperature = n["temperature"].required().number().value_or(0.0);
  const int shapes = n["rectangle"].present() + n["circle"].present() + n["polygon"].present();
  if (shapes != 1) {
    n.problem(R"(give one of "rectangle": [x0, y0, x1, y1], "circle": [x, y, r] or "polygon": [[x, y], ...])");
    return zone;
  }
  if (const Node r = n["rectangle"]; r.present()) {
    zone.numbers = read_numbers(r, 4, "[x0, y0, x1, y1] in m");
    if (zone.numbers.size() == 4 && !(zone.numbers[2] > zone.numbers[0] && zone.numbers[3] > zone.numbers[1]))
      r.problem(fmt::format("x1 must exceed x0 and y1 y0, got {}", r.shown()));
  } else if (const Node c = n["circle"]; c.present()) {
    zone.shape = InitialZone::Shape::circle;
    zone.numbers = read_numbers(c, 3, "[x, y, r] in m");
    if (zone.numbers.size() == 3 && !(zone.numbers[2] > 0.0))
      c.problem(fmt::format("the radius must be positive, got {}", zone.numbers[2]));
  } else {
    const Node p = n["polygon"];
    zone.shape = InitialZone::Shape::polygon;
    const std::size_t size = p.array().value_or(0);
    if (size < 3) p.problem("must list at least three [x, y] corners");
    for (std::size_t k = 0; k < size; ++k)
      if (const auto xy = read_numbers(p[k], 2, "an [x, y] corner in m"); xy.size() == 2)
        zone.corners.push_back({xy[0], xy[1]});
  }
  return zone;
}

}  // namespace

std::vector<InitialZone> read_initial_zones(const Node& n) {
  std::vector<InitialZone> zones;
  if (!n.present()) return zones;
  const std::size_t size = n.array().value_or(0);
  if (n.type() != "array") n.problem("must be a list of zones, got " + n.type());
  for (std::size_t k = 0; k < size; ++k) zones.push_back(read_zone(n[k]));
  return zones;
}

}  // namespace detail

}  // namespace frostwall::project
