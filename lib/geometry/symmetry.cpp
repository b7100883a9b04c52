#include "geometry/symmetry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/core.h>

namespace frostwall::geometry {

namespace {

constexpr double pi = std::numbers::pi;

// x in [0, period).
double wrap(double x, double period) {
  double w = std::fmod(x, period);
  if (w < 0) w += period;
  return w >= period ? 0.0 : w;  // -tiny + period rounds to period
}

// The pipe centres sorted by x, to count the pipes near a point without
// scanning them all for every image of every candidate line.
class PointIndex {
 public:
  explicit PointIndex(const std::vector<Pipe2>& pipes) {
    for (const auto& p : pipes) points_.push_back({p.x, p.y});
    std::sort(points_.begin(), points_.end());
  }
  int count_near(double x, double y, double tolerance) const {
    int n = 0;
    auto it = std::lower_bound(points_.begin(), points_.end(),
                               std::pair{x - tolerance, -std::numeric_limits<double>::infinity()});
    for (; it != points_.end() && it->first <= x + tolerance; ++it)
      if (std::hypot(it->first - x, it->second - y) <= tolerance) ++n;
    return n;
  }

 private:
  std::vector<std::pair<double, double>> points_;
};

// The line at angle phi maps the set onto itself: as many pipes near each
// pipe's image as near the pipe (`multiplicity`), so doubled pipes count.
bool is_mirror(const std::vector<Pipe2>& pipes, const std::vector<int>& multiplicity, const PointIndex& index,
               double phi, double tolerance) {
  const double c = std::cos(2 * phi), s = std::sin(2 * phi);
  for (std::size_t i = 0; i < pipes.size(); ++i) {
    const auto& p = pipes[i];
    if (index.count_near(c * p.x + s * p.y, s * p.x - c * p.y, tolerance) != multiplicity[i]) return false;
  }
  return true;
}

// How far apart two line angles may be and still be the same line: a
// tolerance in metres seen from the reference pipe, with slack for the two
// ends of a difference.
double angular_tolerance(double tolerance, double reference_radius) {
  return std::max(4.0 * tolerance / reference_radius, 1e-12);
}

const Pipe2* farthest_pipe(const std::vector<Pipe2>& pipes) {
  const Pipe2* ref = nullptr;
  for (const auto& p : pipes)
    if (!ref || std::hypot(p.x, p.y) > std::hypot(ref->x, ref->y)) ref = &p;
  return ref;
}

}  // namespace

double default_symmetry_tolerance(const std::vector<Pipe2>& pipes) {
  const Pipe2* ref = farthest_pipe(pipes);
  return ref ? 1e-6 * std::hypot(ref->x, ref->y) : 0.0;
}

std::vector<double> mirror_lines(const std::vector<Pipe2>& pipes, double tolerance) {
  // Every mirror maps the farthest pipe P onto some pipe Q at the same radius,
  // so it is the perpendicular bisector of PQ (the line through P when Q = P).
  // These are all the candidates there are; the lines through other pipes and
  // the bisectors of other pairs add no mirror these miss. The farthest pipe
  // gives the finest angular resolution.
  const Pipe2* ref = farthest_pipe(pipes);
  if (!ref) return {};
  const double r_ref = std::hypot(ref->x, ref->y);
  if (r_ref <= tolerance) return {};
  const double theta_ref = std::atan2(ref->y, ref->x);
  const double same_line = angular_tolerance(tolerance, r_ref);

  std::vector<double> candidates;
  for (const auto& q : pipes)
    if (std::abs(std::hypot(q.x, q.y) - r_ref) <= tolerance)
      candidates.push_back(wrap((theta_ref + std::atan2(q.y, q.x)) / 2, pi));
  std::sort(candidates.begin(), candidates.end());

  const PointIndex index(pipes);
  std::vector<int> multiplicity;
  for (const auto& p : pipes) multiplicity.push_back(index.count_near(p.x, p.y, tolerance));
  std::vector<double> lines;
  for (const double phi : candidates) {
    // Pipes doubled within the tolerance give the same candidate twice; a line
    // just below pi is the same as one just above 0.
    if (!lines.empty() && phi - lines.back() <= same_line) continue;
    if (!lines.empty() && pi - phi + lines.front() <= same_line) continue;
    if (is_mirror(pipes, multiplicity, index, phi, tolerance)) lines.push_back(phi);
  }
  return lines;
}

Wedge find_symmetry_wedge(const std::vector<Pipe2>& pipes, double preferred_start_angle, double tolerance) {
  const double oa = wrap(preferred_start_angle, 2 * pi);
  const Wedge full{0, oa, 2 * pi};
  const auto lines = mirror_lines(pipes, tolerance);
  if (lines.empty()) return full;

  // The mirror lines of a finite set form a dihedral group: M lines pi/M
  // apart. Anything else means the tolerance accepted a near-mirror but not
  // its partners, and a wedge between such lines would not be symmetric.
  const int m = static_cast<int>(lines.size());
  const double width = pi / m;
  const Pipe2& ref = *farthest_pipe(pipes);
  const double same_line = angular_tolerance(tolerance, std::hypot(ref.x, ref.y));
  for (int k = 1; k < m; ++k)
    if (std::abs(lines[k] - lines[0] - k * width) > same_line) return full;

  // Start on the ray at the preferred angle, not on the opposite ray of the
  // same line (that would put OA between pipes for an odd count), or else on
  // the first mirror ray counter-clockwise from it.
  double turn = pi;
  for (const double line : lines) {
    const double d = wrap(line - oa, pi);
    if (d <= same_line || pi - d <= same_line) {
      turn = 0.0;
      break;
    }
    turn = std::min(turn, d);
  }
  return {m, wrap(oa + turn, 2 * pi), width};
}

Wedge find_symmetry_wedge(const std::vector<Pipe2>& pipes, double preferred_start_angle) {
  return find_symmetry_wedge(pipes, preferred_start_angle, default_symmetry_tolerance(pipes));
}

Wedge find_flow_symmetry_wedge(const std::vector<Pipe2>& pipes, double flow_angle, double tolerance,
                               std::string& note) {
  const double along = wrap(flow_angle, 2 * pi);
  const Pipe2* ref = pipes.empty() ? nullptr : farthest_pipe(pipes);
  const double same_line = ref ? angular_tolerance(tolerance, std::hypot(ref->x, ref->y)) : 1e-12;
  const auto lines = mirror_lines(pipes, tolerance);
  const bool no_pipe_off_axis = lines.empty() && (pipes.empty() || std::hypot(ref->x, ref->y) <= tolerance);
  bool mirrored = no_pipe_off_axis;
  for (const double line : lines) {
    const double d = wrap(line - along, pi);
    if (d <= same_line || pi - d <= same_line) mirrored = true;
  }
  if (!mirrored) {
    note = fmt::format(
        "symmetry under seepage: the layout has no mirror line along the flow ({:.3f} deg); the full circle",
        along * 180.0 / pi);
    return {0, along, 2 * pi};
  }
  note =
      fmt::format("symmetry under seepage: only the mirror line along the flow ({:.3f} deg) survives; half the section",
                  along * 180.0 / pi);
  return {1, along, pi};
}

std::string describe(const Wedge& wedge) {
  const double to_deg = 180.0 / pi;
  if (wedge.mirror_count == 0)
    return fmt::format("symmetry: no mirror line, full circle from {:.3f} deg", wedge.start_angle * to_deg);
  return fmt::format("symmetry: {} mirror line{}, wedge of {:.3f} deg from {:.3f} deg", wedge.mirror_count,
                     wedge.mirror_count == 1 ? "" : "s", wedge.angle * to_deg, wedge.start_angle * to_deg);
}

Wedge symmetry_wedge(const project::ShaftSection& section) {
  const auto pipes = pipe_positions(section.layout);
  const double start = section.layout.pattern == project::Pattern::pipes
                           ? std::atan2(pipes.front().y, pipes.front().x)
                           : (section.layout.pattern == project::Pattern::rings
                                  ? section.layout.rings.front().offset_deg
                                  : section.layout.outer_ring.offset_deg) *
                                 M_PI / 180.0;
  return find_symmetry_wedge(pipes, start);
}

}  // namespace frostwall::geometry
