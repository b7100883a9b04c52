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

Intervals intervals(const std::vector<ParameterSpan>& parameters, const Eigen::MatrixXd& J,
                    const std::vector<double>& residuals, std::optional<double> noise) {
  const auto n = static_cast<Eigen::Index>(parameters.size());
  const auto m = static_cast<Eigen::Index>(residuals.size());
  Intervals out;
  double ssr = 0.0;
  for (double r : residuals) ssr += r * r;
  const int dof = static_cast<int>(std::max<Eigen::Index>(1, m - n));
  out.noise = noise ? *noise : std::sqrt(ssr / dof);
  out.t = student_t975(dof);
  Eigen::VectorXd range(n);
  for (Eigen::Index j = 0; j < n; ++j) range(j) = parameters[j].high - parameters[j].low;
  const Eigen::MatrixXd Ju = J * range.asDiagonal();
  const double s2 = std::max(out.noise * out.noise, 1e-300);
  const Eigen::MatrixXd information = Ju.transpose() * Ju / s2 + 12.0 * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd Cu = information.ldlt().solve(Eigen::MatrixXd::Identity(n, n));
  out.covariance = range.asDiagonal() * Cu * range.asDiagonal();
  out.correlation = Eigen::MatrixXd::Identity(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j)
      if (i != j) out.correlation(i, j) = Cu(i, j) / std::sqrt(Cu(i, i) * Cu(j, j));
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& p = parameters[j];
    const double sigma = std::sqrt(out.covariance(j, j));
    out.sigma.push_back(sigma);
    out.low.push_back(std::max(p.low, p.value - out.t * sigma));
    out.high.push_back(std::min(p.high, p.value + out.t * sigma));
    // Not identified: the interval (unclipped) spans more than half the bounds.
    const bool identified = 2.0 * out.t * sigma <= 0.5 * range(j);
    out.identified.push_back(identified);
    if (!identified)
      out.warnings.push_back(fmt::format("{} is not identified by these readings: its 95 % interval spans more than "
                                         "half its bounds [{:g}, {:g}], so the fit says little about it",
                                         p.name, p.low, p.high));
  }
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = i + 1; j < n; ++j)
      if (std::abs(out.correlation(i, j)) > correlation_limit)
        out.warnings.push_back(fmt::format("{} and {} cannot be told apart by these readings (correlation {:+.3f}): "
                                           "the readings fix a combination of the two, not each",
                                           parameters[i].name, parameters[j].name, out.correlation(i, j)));
  return out;
}

}  // namespace frostwall::calibrate
