#include "calibrate/intervals.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace frostwall::calibrate {

double student_t975(int dof) {
  static constexpr double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                                     2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                                     2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return table[0];
  if (dof <= 30) return table[dof - 1];
  return 1.96 + 2.4 / dof;  // within 0.002 of the exact quantile beyond 30
}

namespace {

// The intervals, correlations and warnings of a covariance (in the
// parameters' units).
Intervals from_covariance(const std::vector<ParameterSpan>& parameters, const Eigen::MatrixXd& covariance, double noise,
                          double t) {
  const auto n = static_cast<Eigen::Index>(parameters.size());
  Intervals out;
  out.noise = noise;
  out.t = t;
  out.covariance = covariance;
  out.correlation = Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      if (i != j) out.correlation(i, j) = covariance(i, j) / std::sqrt(covariance(i, i) * covariance(j, j));
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& p = parameters[j];
    const double sigma = std::sqrt(covariance(j, j)), range = p.high - p.low;
    out.sigma.push_back(sigma);
    out.low.push_back(std::max(p.low, p.value - t * sigma));
    out.high.push_back(std::min(p.high, p.value + t * sigma));
    // Not identified: the interval (unclipped) spans more than half the bounds.
    const bool identified = 2.0 * t * sigma <= 0.5 * range;
    out.identified.push_back(identified);
    if (!identified)
      out.warnings.push_back(fmt::format("{} is not identified by these readings: its 95 % interval spans more than "
                                         "half its bounds [{:g}, {:g}], so the fit says little about it",
                                         p.name, p.low, p.high));
  }
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j)
      if (std::abs(out.correlation(i, j)) > correlation_limit)
        out.warnings.push_back(fmt::format(
            "{} and {} are hard to tell apart with these readings (correlation {:+.3f}): the readings fix a "
            "combination of the two better than each, and the intervals are wide along it",
            parameters[i].name, parameters[j].name, out.correlation(i, j)));
  return out;
}

}  // namespace

Intervals intervals(const std::vector<ParameterSpan>& parameters, const Eigen::MatrixXd& J,
                    const std::vector<double>& residuals, std::optional<double> noise) {
  const auto n = static_cast<Eigen::Index>(parameters.size());
  const auto m = static_cast<Eigen::Index>(residuals.size());
  double ssr = 0.0;
  for (double r : residuals) ssr += r * r;
  const int dof = static_cast<int>(std::max<Eigen::Index>(1, m - n));
  const double s = noise ? *noise : std::sqrt(ssr / dof);
  Eigen::VectorXd range(n);
  for (Eigen::Index j = 0; j < n; ++j) range(j) = parameters[j].high - parameters[j].low;
  const Eigen::MatrixXd Ju = J * range.asDiagonal();
  const double s2 = std::max(s * s, 1e-300);
  const Eigen::MatrixXd information = Ju.transpose() * Ju / s2 + 12.0 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd Cu = information.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
  return from_covariance(parameters, range.asDiagonal() * Cu * range.asDiagonal(), s, student_t975(dof));
}

Intervals checked_by_misfit(const std::vector<ParameterSpan>& parameters, const Intervals& linear, double ssr_at_fit,
                            const std::function<std::vector<double>(const std::vector<std::vector<double>>&)>& ssr_at,
                            int* runs) {
  const auto n = static_cast<Eigen::Index>(parameters.size());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> axes(linear.covariance);
  const double t = linear.t, s2 = std::max(linear.noise * linear.noise, 1e-300);
  Eigen::VectorXd x(n);
  for (Eigen::Index j = 0; j < n; ++j) x(j) = parameters[j].value;
  // One side of one axis: the direction of one standard error along it,
  // how far out it was last looked at (in those errors) and its stretch.
  struct Side {
    Eigen::VectorXd unit;
    double reach = 0.0, rise = 0.0, stretch = 1.0;
    bool open = true;
  };
  std::vector<Side> sides;
  for (Eigen::Index k = 0; k < n; ++k)
    for (double sign : {1.0, -1.0})
      sides.push_back({sign * std::sqrt(std::max(axes.eigenvalues()(k), 0.0)) * axes.eigenvectors().col(k)});
  for (int round = 0; round < misfit_rounds; ++round) {
    std::vector<std::vector<double>> points;
    std::vector<std::size_t> asked;
    std::vector<double> at;
    for (std::size_t k = 0; k < sides.size(); ++k) {
      if (!sides[k].open) continue;
      // t, 2t, 4t standard errors out, or to the bound the axis meets first.
      double c = t * std::pow(2.0, round);
      for (Eigen::Index j = 0; j < n; ++j) {
        const double d = sides[k].unit(j);
        if (d > 0.0) c = std::min(c, (parameters[j].high - x(j)) / d);
        if (d < 0.0) c = std::min(c, (parameters[j].low - x(j)) / d);
      }
      if (!(c > sides[k].reach * (1.0 + 1e-9))) {  // at a bound: nothing further to look at
        sides[k].open = false;
        continue;
      }
      const Eigen::VectorXd y = x + c * sides[k].unit;
      points.emplace_back(y.data(), y.data() + n);
      asked.push_back(k);
      at.push_back(c);
    }
    if (points.empty()) break;
    const auto ssr = ssr_at(points);
    if (runs) *runs += static_cast<int>(points.size());
    for (std::size_t q = 0; q < asked.size(); ++q) {
      Side& side = sides[asked[q]];
      const double c = at[q];
      side.rise = (ssr[q] - ssr_at_fit) / s2;
      if (side.rise >= t * t * (1.0 - 1e-3)) {  // reached (to rounding of the sums)
        // Crossed: the misfit rising as (c / g)^2 through this point reaches
        // t^2 at t g; beyond the last point looked at that stayed below.
        side.stretch = std::max({side.stretch, side.reach / t, c / std::sqrt(side.rise)});
        side.open = false;
      } else {
        side.stretch = std::max(side.stretch, c / t);
      }
      side.reach = c;
    }
  }
  for (auto& side : sides)  // still below t^2 at the last look: extrapolated, at most 4 times further
    if (side.open) side.stretch = std::max(side.stretch, side.reach / std::sqrt(std::max(side.rise, t * t / 16.0)));
  Eigen::VectorXd stretched = axes.eigenvalues().cwiseMax(0.0);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double g = std::max({1.0, sides[2 * k].stretch, sides[2 * k + 1].stretch});
    stretched(k) *= g * g;
  }
  const Eigen::MatrixXd C = axes.eigenvectors() * stretched.asDiagonal() * axes.eigenvectors().transpose();
  return from_covariance(parameters, C, linear.noise, t);
}

}  // namespace frostwall::calibrate
