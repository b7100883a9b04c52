#include "post/gap_closure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace frostwall::post {

namespace {

double cross(const particles::Vec<2>& u, const particles::Vec<2>& v) { return u[0] * v[1] - u[1] * v[0]; }

// The gap's sector (free particles between the rays from the ring's centre,
// the origin, through its two pipes, radially within a gap's width of
// them), which wall each touches, and their Delaunay links no longer than
// three local spacings (so none crosses a pipe hole).
void find_sector(Gap& gap, const particles::ParticleSet<2>& P, double pipe_radius) {
  particles::Vec<2> a = gap.from, b = gap.to;
  if (cross(a, b) < 0.0) std::swap(a, b);
  const double width = (gap.to - gap.from).norm();
  const double r_lo = std::min(a.norm(), b.norm()) - width, r_hi = std::max(a.norm(), b.norm()) + width;
  // A mirror line through the gap stands in for the wall beyond it.
  const particles::MirrorPlane<2>* cut = nullptr;
  for (const auto& m : P.mirrors)
    if ((gap.from - m.point).dot(m.normal) * (gap.to - m.point).dot(m.normal) < 0.0) cut = &m;
  std::vector<particles::Vec<2>> where;
  std::vector<double> spacing;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    const particles::Vec<2>& x = P.position[i];
    const double r = x.norm();
    if (r < r_lo || r > r_hi || cross(a, x) < 0.0 || cross(x, b) < 0.0) continue;
    const double near = pipe_radius + P.spacing_of(i);
    char touch = 0;
    if ((x - gap.from).norm() <= near) touch |= 1;
    if ((x - gap.to).norm() <= near) touch |= 2;
    if (cut && std::abs((x - cut->point).dot(cut->normal)) <= 0.75 * P.spacing_of(i))
      touch |= (gap.inside_from == gap.from) ? 2 : 1;
    where.push_back(x);
    spacing.push_back(P.spacing_of(i));
    gap.sector.push_back(std::uint32_t(i));
    gap.touches.push_back(touch);
  }
  std::vector<std::uint32_t> source(where.size());
  std::iota(source.begin(), source.end(), 0u);
  gap.links = delaunay_links(where, source, where.size(), spacing);
}

}  // namespace

GapClosure::GapClosure(const particles::ParticleSet<2>& P, const std::vector<geometry::Pipe2>& pipes,
                       double pipe_radius) {
  // Neighbours: consecutive pipes of each ring, the last back to the first.
  std::map<int, std::vector<const geometry::Pipe2*>> rings;
  for (const auto& pipe : pipes)
    if (pipe.ring >= 0) rings[pipe.ring].push_back(&pipe);
  for (const auto& [ring, members] : rings) {
    if (members.size() < 2) continue;
    for (std::size_t k = 0; k < members.size(); ++k) {
      if (members.size() == 2 && k == 1) break;  // two pipes: one gap
      const auto& a = *members[k];
      const auto& b = *members[(k + 1) % members.size()];
      const particles::Vec<2> pa(a.x, a.y), pb(b.x, b.y), d = pb - pa;
      Gap gap;
      gap.between = a.label + " - " + b.label;
      gap.middle = 0.5 * (pa + pb);
      gap.from = gap.inside_from = pa;
      gap.to = gap.inside_to = pb;
      // A mirror line through the gap (the flow between two pipes): keep the
      // part inside the section; the water through the other is its image.
      for (const auto& m : P.mirrors) {
        const double sa = (pa - m.point).dot(m.normal), sb = (pb - m.point).dot(m.normal);
        if (sa * sb >= 0.0) continue;  // not cut (a pipe on the line is not cut)
        const particles::Vec<2> cut = pa + sa / (sa - sb) * d;
        const double inside = (P.position.front() - m.point).dot(m.normal);  // the section's side
        (sa * inside < 0.0 ? gap.inside_from : gap.inside_to) = cut;
        gap.copies = 2.0;
      }
      for (std::size_t i = 0; i < P.n_free; ++i) {
        const double s = std::clamp((P.position[i] - pa).dot(d) / d.squaredNorm(), 0.0, 1.0);
        if ((P.position[i] - (pa + s * d)).norm() <= 0.75 * P.spacing_of(i)) gap.along.push_back(std::uint32_t(i));
      }
      if (gap.along.empty()) continue;
      find_sector(gap, P, pipe_radius);
      gaps_.push_back(std::move(gap));
    }
  }
}

double GapClosure::bottleneck(const Gap& gap, const std::vector<double>& g) {
  // Kruskal-like: add the sector's particles from the most frozen up,
  // joining linked ones; the level at which one component first touches
  // both walls is the bottleneck.
  order_.resize(gap.sector.size());
  std::iota(order_.begin(), order_.end(), 0u);
  std::sort(order_.begin(), order_.end(),
            [&](std::uint32_t u, std::uint32_t v) { return g[gap.sector[u]] < g[gap.sector[v]]; });
  const auto last = join_.first_holding(gap.links, order_, gap.touches, 3);
  return last ? g[gap.sector[*last]] : std::numeric_limits<double>::infinity();  // the walls are not linked
}

std::optional<double> GapClosure::time_to_fall(double change) const {
  std::optional<double> soonest;
  for (const auto& gap : gaps_)
    if (!gap.closed && gap.worst < 1.0 && gap.falling > 0.0)
      soonest = std::min(soonest.value_or(change / gap.falling), change / gap.falling);
  return soonest;
}

void GapClosure::observe(double t, const std::vector<double>& g) {
  // The time a measure falling from `before` to `now` crossed 0 (linear between observations).
  auto crossing = [&](double before, double now) {
    return before > 0.0 && t > last_t_ ? last_t_ + (t - last_t_) * before / (before - now) : t;
  };
  for (auto& gap : gaps_) {
    double bridge = -1e300;
    for (std::uint32_t i : gap.along) bridge = std::max(bridge, g[i]);
    if (!gap.bridge_closed && bridge <= 0.0) gap.bridge_closed = crossing(gap.bridge_worst, bridge);
    gap.bridge_worst = bridge;
    if (gap.closed) continue;
    const double worst = std::min(bottleneck(gap, g), bridge);
    if (worst <= 0.0) gap.closed = crossing(gap.worst, worst);
    gap.falling = t > last_t_ ? (gap.worst - worst) / (t - last_t_) : 0.0;
    gap.worst = worst;
  }
  last_t_ = t;
}

namespace {

// Does the segment p -> q cross a -> b (p on the left of a -> b, q not)?
// The sign of the crossing: +1 left to right, -1 right to left, 0 none.
int crossing(const particles::Vec<2>& a, const particles::Vec<2>& b, const particles::Vec<2>& p,
             const particles::Vec<2>& q) {
  auto side = [](const particles::Vec<2>& u, const particles::Vec<2>& v, const particles::Vec<2>& w) {
    return (v[0] - u[0]) * (w[1] - u[1]) - (v[1] - u[1]) * (w[0] - u[0]);
  };
  const double sp = side(a, b, p), sq = side(a, b, q);
  if ((sp > 0.0) == (sq > 0.0)) return 0;
  const double sa = side(p, q, a), sb = side(p, q, b);
  if ((sa > 0.0) == (sb > 0.0)) return 0;
  return sp > 0.0 ? 1 : -1;
}

}  // namespace

void GapClosure::observe_flow(double t, const particles::ParticleSet<2>& P, const particles::PairWeights& pairs,
                              const std::vector<double>& Q) {
  for (auto& gap : gaps_) {
    // Only particles within reach of the segment can pair across it.
    const particles::Vec<2> d = gap.to - gap.from;
    const double reach = 0.5 * d.norm() + 4.0 * P.spacing_of(gap.along.front()) + 0.5;
    double through = 0.0;
    for (std::size_t i = 0; i < pairs.n_free; ++i) {
      if ((P.position[i] - gap.middle).norm() > reach) continue;
      for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
        if (Q[e] == 0.0) continue;
        const std::uint32_t j = pairs.column[e];
        const particles::Vec<2> xj = P.position[i] + particles::Vec<2>(pairs.vector[2 * e], pairs.vector[2 * e + 1]);
        const int sign = crossing(gap.inside_from, gap.inside_to, P.position[i], xj);
        if (sign == 0) continue;
        // A pair between two particles of the section is stored in both
        // rows (the halves add up to its flux); a pair to a mirror image
        // in one (its other row is the image of the crossing, elsewhere).
        const bool image = (xj - P.position[j]).squaredNorm() > 1e-12 * P.spacing_of(i) * P.spacing_of(i);
        through += sign * Q[e] * (image ? 1.0 : 0.5);
      }
    }
    gap.flow.emplace_back(t, gap.copies * std::abs(through));
  }
}

const Gap* GapClosure::last() const {
  const Gap* last = nullptr;
  auto later = [](const Gap& a, const Gap& b) {  // is a later (or more open) than b?
    if (a.closed && b.closed) return *a.closed > *b.closed;
    if (!a.closed && !b.closed) return a.worst > b.worst;
    return !a.closed;
  };
  for (const auto& gap : gaps_)
    if (!last || later(gap, *last)) last = &gap;
  return last;
}

}  // namespace frostwall::post
