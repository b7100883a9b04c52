#include "geometry/as_built.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <map>
#include <numeric>

namespace frostwall::geometry {

std::vector<Pipe2> pipes_at(const std::vector<PipeTrace>& traces, const std::vector<Pipe2>& design, double z) {
  std::vector<Pipe2> pipes;
  for (std::size_t k = 0; k < design.size() && k < traces.size(); ++k) {
    if (traces[k].bottom < z) continue;
    Pipe2 p = design[k];
    const auto xy = traces[k].at(z);
    p.x = xy[0], p.y = xy[1];
    pipes.push_back(p);
  }
  return pipes;
}

std::vector<RingGap> largest_gaps(const std::vector<Pipe2>& pipes, double diameter) {
  std::map<int, std::vector<const Pipe2*>> rings;
  for (const auto& p : pipes)
    if (!p.failed) rings[p.ring].push_back(&p);
  std::vector<RingGap> gaps;
  for (auto& [ring, members] : rings) {
    if (members.size() < 2) continue;
    if (ring < 0)
      std::sort(members.begin(), members.end(),
                [](const Pipe2* a, const Pipe2* b) { return std::atan2(a->y, a->x) < std::atan2(b->y, b->x); });
    else std::sort(members.begin(), members.end(), [](const Pipe2* a, const Pipe2* b) { return a->index < b->index; });
    RingGap widest{ring, -1e300, 0, 0, 0.0, 0.0};
    for (std::size_t i = 0; i < members.size(); ++i) {
      const Pipe2 &a = *members[i], &b = *members[(i + 1) % members.size()];
      const double gap = std::hypot(b.x - a.x, b.y - a.y) - diameter;
      if (gap > widest.gap) widest = {ring, gap, a.number, b.number, 0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
    }
    gaps.push_back(widest);
  }
  return gaps;
}

double largest_gap(const std::vector<Pipe2>& pipes, double diameter) {
  double widest = 0.0;
  for (const auto& g : largest_gaps(pipes, diameter)) widest = std::max(widest, g.gap);
  return widest;
}

namespace {

double deepest_bottom(const std::vector<PipeTrace>& traces) {
  double d = 0.0;
  for (const auto& t : traces) d = std::max(d, t.bottom);
  return d;
}

// Every trace point's depth and one every half metre: where a gap is searched.
std::vector<double> search_depths(const std::vector<PipeTrace>& traces, double top, double bottom) {
  std::vector<double> z;
  for (double d = top; d < bottom; d += 0.5) z.push_back(d);
  z.push_back(bottom);
  for (const auto& t : traces)
    for (const auto& p : t.points)
      if (p.z >= top && p.z <= bottom) z.push_back(p.z);
  for (const auto& t : traces)
    if (t.bottom >= top && t.bottom <= bottom) z.push_back(t.bottom);
  std::sort(z.begin(), z.end());
  return z;
}

}  // namespace

std::vector<DepthRange> layer_ranges(const project::Project& p, double deepest) {
  if (p.layers.empty()) return {{0.0, deepest, -1}};
  std::vector<int> order(p.layers.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return p.layers[a].depth < p.layers[b].depth; });
  std::vector<DepthRange> ranges(p.layers.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    const double here = p.layers[order[i]].depth;
    const double top = i == 0 ? 0.0 : 0.5 * (p.layers[order[i - 1]].depth + here);
    const double bottom = i + 1 == order.size() ? std::max(deepest, here) : 0.5 * (here + p.layers[order[i + 1]].depth);
    ranges[order[i]] = {top, bottom, order[i]};
  }
  return ranges;
}

std::vector<double> section_depths(const project::Project& p, const std::vector<PipeTrace>& traces,
                                   const std::vector<Pipe2>& design) {
  const double deepest = deepest_bottom(traces);
  const double diameter = std::get<project::ShaftSection>(p.geometry).pipe.diameter;
  std::vector<double> depths = p.sections.depths;
  if (depths.empty() && p.sections.every)
    for (double d = *p.sections.every; d <= deepest + 1e-9; d += *p.sections.every) depths.push_back(d);
  if (depths.empty()) {
    for (const auto& range : layer_ranges(p, deepest)) {
      const double own = range.layer >= 0 ? p.layers[range.layer].depth
                                          : p.design.depth.value_or(0.5 * (range.top + range.bottom));
      if (own <= deepest) depths.push_back(own);
      double widest = -1e300, at = range.bottom;
      for (const double z : search_depths(traces, range.top, std::min(range.bottom, deepest)))
        if (const double g = largest_gap(pipes_at(traces, design, z), diameter); g > widest + 1e-9) widest = g, at = z;
      if (at <= deepest) depths.push_back(at);
    }
  }
  std::sort(depths.begin(), depths.end());
  std::vector<double> kept;
  for (const double d : depths)
    if (kept.empty() || d - kept.back() >= 0.1) kept.push_back(d);
  return kept;
}

std::vector<std::string> as_built_problems(const project::Project& p, const std::vector<PipeTrace>& traces,
                                           const std::vector<Pipe2>& design) {
  std::vector<std::string> problems;
  if (!p.survey) return problems;
  const double deepest = deepest_bottom(traces);
  for (std::size_t k = 0; k < p.sections.depths.size(); ++k)
    if (p.sections.depths[k] > deepest)
      problems.push_back(fmt::format("sections.depths[{}]: {} m is below every pipe (the deepest ends at {:.2f} m)", k,
                                     p.sections.depths[k], deepest));
  // Crossing pipes: every pair at every depth a position is known at, and
  // every half metre between; one line per pair, at its first crossing.
  const double diameter = std::get<project::ShaftSection>(p.geometry).pipe.diameter;
  const auto depths = search_depths(traces, 0.0, deepest);
  for (std::size_t a = 0; a < traces.size(); ++a)
    for (std::size_t b = a + 1; b < traces.size(); ++b)
      for (const double z : depths) {
        if (z > traces[a].bottom || z > traces[b].bottom) break;
        const auto pa = traces[a].at(z), pb = traces[b].at(z);
        const double c = std::hypot(pa[0] - pb[0], pa[1] - pb[1]);
        if (c >= diameter) continue;
        // Each pipe's survey row at or next below the crossing.
        auto row_below = [&](const PipeTrace& t) {
          for (const auto& q : t.points)
            if (q.line > 0 && q.z >= z - 1e-9) return q.line;
          return t.points.back().line;
        };
        problems.push_back(fmt::format("survey.file: {} lines {} and {}: pipes {} and {} cross at {:.2f} m depth "
                                       "(centres {:.3f} m apart, pipe diameter {:.3f} m)",
                                       p.survey->file, row_below(traces[a]), row_below(traces[b]), design[a].number,
                                       design[b].number, z, c, diameter));
        break;
      }
  return problems;
}

}  // namespace frostwall::geometry
