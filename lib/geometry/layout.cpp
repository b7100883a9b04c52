#include "geometry/layout.hpp"
#include "pipes/pipe_exchange.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/core.h>

namespace frostwall::geometry {

namespace {

using project::Layout;
using project::Pattern;

constexpr double deg = std::numbers::pi / 180.0;

// A ring of equally spaced pipes, with the words a problem line uses for it.
struct RegularRing {
  double radius = 0.0;
  int count = 0;
  double first = 0.0;       // rad, angle of pipe 0
  double spacing = 0.0;     // rad, between neighbours
  std::string path;         // what to change for an overlap: "layout.outer_ring", "layout.inner_ring.radius"
  std::string radius_path;  // what to change for the excavation
  std::string name;         // the ring in prose: "layout.outer_ring"
  std::string pipes;        // its pipes as a subject: "inner-ring pipes"
  std::string theirs;       // its pipes as an object: "the outer ring's"
  std::string label;        // prefix of a pipe label: "outer ", "ring 1 pipe "

  double angle(int k) const { return first + k * spacing; }
};

// The regular rings of a ring pattern, in the order pipe_positions lists them.
// Empty for measured pipes.
std::vector<RegularRing> regular_rings(const Layout& layout) {
  std::vector<RegularRing> rings;
  const auto& outer = layout.outer_ring;
  const auto equally_spaced = [](double radius, int count, double first_deg) {
    RegularRing r;
    r.radius = radius;
    r.count = count;
    r.first = first_deg * deg;
    r.spacing = count > 0 ? 2.0 * std::numbers::pi / count : 0.0;
    return r;
  };
  switch (layout.pattern) {
    case Pattern::single:
    case Pattern::three_hole:
    case Pattern::four_hole: {
      auto o = equally_spaced(outer.radius, outer.count, outer.offset_deg);
      o.path = o.name = "layout.outer_ring";
      o.radius_path = "layout.outer_ring.radius";
      o.pipes = "outer-ring pipes";
      o.theirs = "the outer ring's";
      o.label = "outer ";
      rings.push_back(o);
      if (layout.pattern == Pattern::single || !layout.inner_ring_radius || outer.count < 1) break;
      const double half = 180.0 / outer.count;  // half the outer spacing, degrees
      auto i = layout.pattern == Pattern::three_hole
                   ? equally_spaced(*layout.inner_ring_radius, outer.count, outer.offset_deg + half)
                   : equally_spaced(*layout.inner_ring_radius, 2 * outer.count, outer.offset_deg);
      // The inner ring's count and angle follow the outer ring: its radius is
      // the only thing of its own the user can change.
      i.path = i.radius_path = "layout.inner_ring.radius";
      i.name = "layout.inner_ring";
      i.pipes = "inner-ring pipes";
      i.theirs = "the inner ring's";
      i.label = "inner ";
      rings.push_back(i);
      break;
    }
    case Pattern::rings:
      for (std::size_t n = 0; n < layout.rings.size(); ++n) {
        const auto& ring = layout.rings[n];
        auto r = equally_spaced(ring.radius, ring.count, ring.offset_deg);
        r.path = r.name = fmt::format("layout.rings[{}]", n);
        r.radius_path = r.path + ".radius";
        r.pipes = "pipes";
        r.theirs = "those of " + r.path;
        r.label = fmt::format("ring {} pipe ", n);
        rings.push_back(r);
      }
      break;
    case Pattern::pipes: break;
  }
  return rings;
}

double chord(double r1, double r2, double angle_between) {
  // Law of cosines; clamp the round-off that could make coincident pipes NaN.
  return std::sqrt(std::max(0.0, r1 * r1 + r2 * r2 - 2.0 * r1 * r2 * std::cos(angle_between)));
}

// Closest centres of two regular rings. For each pipe of `a` only the two
// pipes of `b` on either side of its angle can be nearest (radii are fixed),
// so this is linear in a's count however many pipes the rings have.
double closest_centres(const RegularRing& a, const RegularRing& b) {
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < a.count; ++k) {
    const double u = a.angle(k) - b.first;
    const double below = std::floor(u / b.spacing) * b.spacing;
    best = std::min({best, chord(a.radius, b.radius, u - below), chord(a.radius, b.radius, below + b.spacing - u)});
  }
  return best;
}

// The pipe that reaches farthest from the shaft axis, named for a problem line.
struct Farthest {
  double reach = -std::numeric_limits<double>::infinity();  // centre radius + half the diameter
  std::string who;
};

}  // namespace

std::vector<Pipe2> all_pipe_positions(const Layout& layout) {
  std::vector<Pipe2> pipes;
  if (layout.pattern == Pattern::pipes) {
    for (std::size_t k = 0; k < layout.pipes.size(); ++k)
      pipes.push_back({layout.pipes[k].x, layout.pipes[k].y, -1, static_cast<int>(k), fmt::format("pipe {}", k)});
  } else {
    const auto rings = regular_rings(layout);
    for (std::size_t n = 0; n < rings.size(); ++n) {
      const auto& ring = rings[n];
      for (int k = 0; k < ring.count; ++k)
        pipes.push_back({ring.radius * std::cos(ring.angle(k)), ring.radius * std::sin(ring.angle(k)),
                         static_cast<int>(n), k, ring.label + std::to_string(k)});
    }
  }
  for (std::size_t k = 0; k < pipes.size(); ++k) {
    pipes[k].number = static_cast<int>(k) + 1;
    pipes[k].failed = std::find(layout.failed_pipes.begin(), layout.failed_pipes.end(), pipes[k].number) !=
                      layout.failed_pipes.end();
  }
  return pipes;
}

std::vector<Pipe2> pipe_positions(const Layout& layout) {
  auto pipes = all_pipe_positions(layout);
  std::erase_if(pipes, [](const Pipe2& p) { return p.failed; });
  return pipes;
}

std::vector<std::string> layout_problems(const project::ShaftSection& section) {
  std::vector<std::string> problems;
  const auto& layout = section.layout;
  const double d = std::max(section.pipe.diameter, 0.0);  // a bad diameter is the loader's line
  const std::optional<double> excavation = section.shaft.excavation_radius;
  Farthest farthest;

  if (layout.pattern == Pattern::pipes) {
    // Measured pipes: every pair, every pipe; a survey lists tens, not thousands.
    const auto& p = layout.pipes;
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = i + 1; j < p.size(); ++j)
        if (const double c = std::hypot(p[i].x - p[j].x, p[i].y - p[j].y); c < d)
          problems.push_back(fmt::format("layout.pipes[{}]: overlaps layout.pipes[{}] (centres {:.3f} m apart, "
                                         "pipe diameter {:.3f} m)",
                                         i, j, c, d));
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double r = std::hypot(p[i].x, p[i].y);
      if (excavation && r - d / 2 < *excavation)
        problems.push_back(fmt::format("layout.pipes[{}]: the pipe reaches into the excavation (its wall {:.3f} m "
                                       "from the shaft axis, shaft.excavation_radius {:.3f} m)",
                                       i, r - d / 2, *excavation));
      if (r + d / 2 > farthest.reach) farthest = {r + d / 2, fmt::format("layout.pipes[{}]", i)};
    }
  } else {
    const auto rings = regular_rings(layout);
    // Within a ring neighbours are closest; between rings, one line per pair of
    // rings (not per pipe: 26 identical lines would bury the message).
    for (const auto& ring : rings)
      if (ring.count >= 2)
        if (const double c = chord(ring.radius, ring.radius, ring.spacing); c < d)
          problems.push_back(fmt::format("{}: {} pipes on radius {:.3f} m overlap their neighbours (centres {:.3f} m "
                                         "apart, pipe diameter {:.3f} m)",
                                         ring.path, ring.count, ring.radius, c, d));
    for (std::size_t b = 0; b < rings.size(); ++b)
      for (std::size_t a = 0; a < b; ++a)
        if (rings[a].count > 0 && rings[b].count > 0)
          if (const double c = closest_centres(rings[b], rings[a]); c < d)
            problems.push_back(fmt::format("{}: {} overlap {} (closest centres {:.3f} m apart, pipe diameter {:.3f} m)",
                                           rings[b].path, rings[b].pipes, rings[a].theirs, c, d));
    for (const auto& ring : rings) {
      if (ring.count < 1) continue;
      if (excavation && ring.radius - d / 2 < *excavation)
        problems.push_back(fmt::format("{}: {} reach into the excavation (their wall {:.3f} m from the shaft axis, "
                                       "shaft.excavation_radius {:.3f} m)",
                                       ring.radius_path, ring.pipes, ring.radius - d / 2, *excavation));
      if (ring.radius + d / 2 > farthest.reach) farthest = {ring.radius + d / 2, "the pipes of " + ring.name};
    }
  }

  // One line for the far field, naming the pipe that decides how large it must be.
  const double far = section.outer_radius;
  const bool disc = pipes::make_pipe_exchange(section.pipe.model)->rings_on_wall();
  const double clearance = disc ? far_field_clearance_diameters * d : 0.0;
  if (far > 0 && !farthest.who.empty()) {
    if (farthest.reach > far)
      problems.push_back(
          fmt::format("domain.outer_radius: the far-field circle of {:.3f} m cuts through pipe discs ({} "
                      "reaching {:.3f} m from the shaft axis); it must be at least {:.3f} m{}",
                      far, farthest.who, farthest.reach, farthest.reach + clearance,
                      disc ? fmt::format(" (the disc model needs {:g} pipe diameters of soil beyond "
                                         "the pipes)",
                                         far_field_clearance_diameters)
                           : ""));
    else if (farthest.reach + clearance > far)
      problems.push_back(fmt::format("domain.outer_radius: the far-field circle of {:.3f} m is only {:.3f} m from "
                                     "{} (reaching {:.3f} m); the disc model needs {:g} pipe diameters ({:.3f} m) "
                                     "of soil there, so at least {:.3f} m",
                                     far, far - farthest.reach, farthest.who, farthest.reach,
                                     far_field_clearance_diameters, clearance, farthest.reach + clearance));
  }
  return problems;
}

}  // namespace frostwall::geometry
