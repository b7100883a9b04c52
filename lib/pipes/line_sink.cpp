#include "pipes/line_sink.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <numbers>
#include <map>
#include <stdexcept>
#include <tuple>

namespace frostwall::pipes {

namespace {

using particles::PairWeights;

// The fit of one pipe: the smallest weighted change from x0 = (1 for each
// pair factor, the particle's exchange weight from its row alone) that makes
// every equation A x = b exact, with x >= 0. Changes to the exchange weights
// cost `exchange_cost` of what changes to the pair factors cost.
struct LinearFit {
  Eigen::MatrixXd A;
  Eigen::VectorXd b, x0, cost;
};

// Weighted minimum-norm solution of A x = b near x0; variables that come
// out negative are held at 0 and the rest solved again (an active set that
// only grows: each pass removes at least one variable).
Eigen::VectorXd solve_nonnegative(const LinearFit& fit) {
  const long n = fit.A.cols();
  std::vector<char> held(static_cast<std::size_t>(n), 0);
  Eigen::VectorXd x = fit.x0;
  for (long pass = 0; pass <= n; ++pass) {
    Eigen::VectorXd inverse_cost(n), start = fit.x0;
    for (long k = 0; k < n; ++k) {
      inverse_cost(k) = held[std::size_t(k)] ? 0.0 : 1.0 / fit.cost(k);
      if (held[std::size_t(k)]) start(k) = 0.0;
    }
    const Eigen::MatrixXd AW = fit.A * inverse_cost.asDiagonal();
    Eigen::MatrixXd M = AW * fit.A.transpose();
    M.diagonal().array() += 1e-12 * M.diagonal().maxCoeff();
    x = start + AW.transpose() * M.ldlt().solve(fit.b - fit.A * start);
    bool negative = false;
    for (long k = 0; k < n; ++k)
      if (!held[std::size_t(k)] && x(k) < 0.0) held[std::size_t(k)] = 1, negative = true;
    if (!negative) break;
  }
  return x.cwiseMax(0.0);
}

// One pipe: which particles are near, which pair entries share a factor.
struct PipeFit {
  std::vector<std::uint32_t> near;  // free particles
  std::vector<int> equation;        // per particle: its row in `near`, -1 if not near
  // The factor of each entry of the near particles' rows (-1: fixed), the
  // entries of near[q]'s row from first[q] on.
  std::vector<int> variable;
  std::vector<std::size_t> first;
  std::vector<double> row_sum;  // D_i = sum_e |G_e| of near[q]'s row before the fit
  int factor(const PairWeights& pairs, std::size_t q, std::size_t e) const {
    return variable[first[q] + (e - pairs.row_start[near[q]])];
  }
  std::size_t factors = 0;
};

PipeFit find_near(const PairWeights& pairs, const particles::ParticleSet<2>& P, const LineSinkNode& node,
                  const LineSinkOptions& options) {
  PipeFit fit;
  fit.equation.assign(pairs.n_free, -1);
  for (std::uint32_t i = 0; i < pairs.n_free; ++i) {
    const double r = (P.position[i] - node.centre).norm();
    if (r < node.radius + options.reach * P.spacing_of(i)) {
      if (r <= node.radius) throw std::logic_error("couple_line_sinks: a particle inside a pipe's wall");
      fit.equation[i] = static_cast<int>(fit.near.size());
      fit.near.push_back(i);
    }
  }
  // The two halves of a pair (i sees j, j sees i, directly or through the
  // same mirror) have the same length: they share one factor.
  std::map<std::tuple<std::uint32_t, std::uint32_t, long long>, int> factor_of;
  for (std::uint32_t i : fit.near) {
    fit.first.push_back(fit.variable.size());
    fit.row_sum.push_back(0.0);
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e)
      fit.row_sum.back() += std::abs(pairs.weight[e]);
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      fit.variable.push_back(-1);
      const std::uint32_t j = pairs.column[e];
      if (j >= pairs.n_free || fit.equation[j] < 0) continue;
      const double length = Vec<2>(pairs.vector[2 * e], pairs.vector[2 * e + 1]).norm();
      const auto key = std::make_tuple(std::min(i, j), std::max(i, j), std::llround(length / P.spacing * 1e8));
      const auto [it, added] = factor_of.emplace(key, static_cast<int>(fit.factors));
      if (added) ++fit.factors;
      fit.variable.back() = it->second;
    }
  }
  return fit;
}

// The fields the operator is made exact for round a pipe: the logarithm
// (the pipe's own heat) and the two dipoles (r - a^2/r)(cos, sin) (a uniform
// gradient past an isothermal pipe); each is 0 on the wall.
constexpr int exact_fields = 3;
std::array<double, exact_fields> fields_at(const Vec<2>& y, const LineSinkNode& node) {
  const Vec<2> d = y - node.centre;
  const double r = d.norm(), radial = 1.0 - node.radius * node.radius / (r * r);
  return {std::log(r / node.radius), radial * d[0], radial * d[1]};
}

// The rows of the fit: each field exact at each near particle (scaled by
// the particle's row sum D_i, the exchange weight as w_i / D_i), then the
// heat the logarithm draws, exactly 2 pi k times the share of the wall in
// the section.
LinearFit assemble(const PairWeights& pairs, const particles::ParticleSet<2>& P, const LineSinkNode& node,
                   const PipeFit& fit, const LineSinkOptions& options) {
  const std::size_t m = fit.near.size(), n = fit.factors + m;
  const long rows = static_cast<long>(exact_fields * m + 1);
  LinearFit lin{Eigen::MatrixXd::Zero(rows, static_cast<long>(n)), Eigen::VectorXd::Zero(rows),
                Eigen::VectorXd::Ones(static_cast<long>(n)), Eigen::VectorXd::Ones(static_cast<long>(n))};
  for (std::size_t q = 0; q < m; ++q) {
    const std::uint32_t i = fit.near[q];
    const Vec<2> xi = P.position[i];
    const auto fi = fields_at(xi, node);
    const double row_sum = fit.row_sum[q], s = 1.0 / row_sum;
    double own_row = 0.0;  // the logarithm's row with every factor at 1
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      const auto fj = fields_at(xi + Vec<2>(pairs.vector[2 * e], pairs.vector[2 * e + 1]), node);
      own_row += s * pairs.weight[e] * (fj[0] - fi[0]);
      for (int f = 0; f < exact_fields; ++f) {
        const long row = static_cast<long>(exact_fields * q) + f;
        const double term = s * pairs.weight[e] * (fj[f] - fi[f]);
        if (const int v = fit.factor(pairs, q, e); v >= 0) lin.A(row, v) += term;
        else lin.b(row) -= term;
      }
    }
    const long w = static_cast<long>(fit.factors + q);
    lin.cost(w) = options.exchange_cost;
    lin.x0(w) = 0.0;
    if ((xi - node.centre).norm() > node.radius + options.exchange_reach * P.spacing_of(i)) continue;
    for (int f = 0; f < exact_fields; ++f) lin.A(static_cast<long>(exact_fields * q) + f, w) = -fi[f];
    lin.A(rows - 1, w) = P.volume[i] * row_sum * fi[0] / (std::numbers::pi * node.share);
    lin.x0(w) = std::max(0.0, own_row / fi[0]);
  }
  lin.b(rows - 1) = 1.0;
  return lin;
}

// The pair list without the pairs to `drop`, with the exchange pairs
// (i, node, weight) added at the end of their rows.
struct Exchange {
  std::uint32_t row, node;
  double weight;
  Vec<2> vector;
};

PairWeights rebuilt(const PairWeights& pairs, const std::vector<char>& drop, const std::vector<Exchange>& exchange) {
  PairWeights out = pairs;
  out.column.clear();
  out.weight.clear();
  out.vector.clear();
  out.direction2.clear();
  std::vector<std::vector<const Exchange*>> added(pairs.n_free);
  for (const auto& x : exchange) added[x.row].push_back(&x);
  const bool directions = !pairs.direction2.empty(), vectors = !pairs.vector.empty();
  out.row_start.assign(1, 0);
  for (std::size_t i = 0; i < pairs.n_free; ++i) {
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      if (drop[pairs.column[e]]) continue;
      out.column.push_back(pairs.column[e]);
      out.weight.push_back(pairs.weight[e]);
      for (int d = 0; d < 2; ++d) {
        if (vectors) out.vector.push_back(pairs.vector[2 * e + d]);
        if (directions) out.direction2.push_back(pairs.direction2[2 * e + d]);
      }
    }
    for (const Exchange* x : added[i]) {
      out.column.push_back(x->node);
      out.weight.push_back(x->weight);
      const double r2 = x->vector.squaredNorm();
      for (int d = 0; d < 2; ++d) {
        if (vectors) out.vector.push_back(x->vector[d]);
        if (directions) out.direction2.push_back(x->vector[d] * x->vector[d] / r2);
      }
    }
    out.row_start.push_back(out.column.size());
  }
  return out;
}

}  // namespace

std::vector<LineSinkFit> couple_line_sinks(PairWeights& pairs, const particles::ParticleSet<2>& P,
                                           const std::vector<LineSinkNode>& nodes, const LineSinkOptions& options) {
  if (pairs.vector.empty()) throw std::logic_error("couple_line_sinks: the pairs must keep their vectors");
  std::vector<char> drop(P.size(), 0);
  for (const auto& node : nodes) drop[node.node] = 1;
  // The SPH pairs to the nodes go first: the fit replaces them.
  pairs = rebuilt(pairs, drop, {});
  std::fill(drop.begin(), drop.end(), 0);

  std::vector<LineSinkFit> fits;
  std::vector<Exchange> exchange;
  for (const auto& node : nodes) {
    const PipeFit fit = find_near(pairs, P, node, options);
    const LinearFit lin = assemble(pairs, P, node, fit, options);
    const Eigen::VectorXd x = solve_nonnegative(lin);
    const Eigen::VectorXd r = lin.A * x - lin.b;

    LineSinkFit report;
    report.near = fit.near.size();
    report.pairs = fit.factors;
    report.residual = r.cwiseAbs().maxCoeff();
    for (std::size_t p = 0; p < fit.factors; ++p)
      report.largest_change = std::max(report.largest_change, std::abs(x(static_cast<long>(p)) - 1.0));
    for (std::size_t q = 0; q < fit.near.size(); ++q)
      for (std::size_t e = pairs.row_start[fit.near[q]]; e < pairs.row_start[fit.near[q] + 1]; ++e)
        if (const int v = fit.factor(pairs, q, e); v >= 0) pairs.weight[e] *= x(v);
    for (std::size_t q = 0; q < fit.near.size(); ++q) {
      const std::uint32_t i = fit.near[q];
      const double w = x(static_cast<long>(fit.factors + q)) * fit.row_sum[q];
      if (w <= 0.0) continue;
      ++report.exchanging;
      exchange.push_back({i, node.node, w, node.centre - P.position[i]});
    }
    fits.push_back(report);
  }
  pairs = rebuilt(pairs, drop, exchange);
  return fits;
}

}  // namespace frostwall::pipes
