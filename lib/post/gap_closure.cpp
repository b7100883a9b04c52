#include "post/gap_closure.hpp"

#include <algorithm>
#include <map>

namespace frostwall::post {

GapClosure::GapClosure(const particles::ParticleSet<2>& P, const std::vector<geometry::Pipe2>& pipes) {
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
        if ((sa < 0.0) == (sb < 0.0)) continue;
        const particles::Vec<2> cut = pa + sa / (sa - sb) * d;
        (sa < 0.0 ? gap.inside_from : gap.inside_to) = cut;
        gap.copies = 2.0;
      }
      for (std::size_t i = 0; i < P.n_free; ++i) {
        const double s = std::clamp((P.position[i] - pa).dot(d) / d.squaredNorm(), 0.0, 1.0);
        if ((P.position[i] - (pa + s * d)).norm() <= 0.75 * P.spacing_of(i)) gap.along.push_back(std::uint32_t(i));
      }
      if (!gap.along.empty()) gaps_.push_back(std::move(gap));
    }
  }
}

std::optional<double> GapClosure::time_to_fall(double change) const {
  std::optional<double> soonest;
  for (const auto& gap : gaps_)
    if (!gap.closed && gap.worst < 1.0 && gap.falling > 0.0)
      soonest = std::min(soonest.value_or(change / gap.falling), change / gap.falling);
  return soonest;
}

void GapClosure::observe(double t, const std::vector<double>& g) {
  for (auto& gap : gaps_) {
    double worst = -1e300;
    for (std::uint32_t i : gap.along) worst = std::max(worst, g[i]);
    if (!gap.closed && worst <= 0.0)
      gap.closed = gap.worst > 0.0 && t > last_t_ ? last_t_ + (t - last_t_) * gap.worst / (gap.worst - worst) : t;
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
