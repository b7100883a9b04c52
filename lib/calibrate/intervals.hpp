// What the readings say about the fitted parameters: their 95 % intervals
// from the Jacobian at the optimum, their correlations, and plain warnings
// where the readings cannot tell two parameters apart or leave one
// unidentified.
//
// The residual variance s^2 is the thermometers' noise squared when given,
// else the misfit at the optimum, SSR / (m - n). In parameters scaled to
// their bounds (u = (x - low) / (high - low)) the information of the
// readings is F = J_u^T J_u / s^2; the covariance is (F + P)^-1 with P =
// 12 I, the precision of a uniform spread over the bounds. Where the
// readings inform a parameter well, P is negligible and this is the usual
// s^2 (J^T J)^-1; where they do not, the interval is the bounds instead
// of infinite. The interval is value +- t sigma (Student's t at 97.5 %,
// m - n degrees of freedom), clipped to the bounds.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace frostwall::calibrate {

struct ParameterSpan {
  std::string name;
  double value = 0.0, low = 0.0, high = 0.0;  // the fit and its bounds
};

struct Intervals {
  std::vector<double> sigma;      // standard error, in the parameter's unit
  std::vector<double> low, high;  // the 95 % interval, within the bounds
  std::vector<bool> identified;   // false: the interval spans more than half the bounds
  Eigen::MatrixXd covariance;     // in the parameters' units
  Eigen::MatrixXd correlation;
  double noise = 0.0;  // s, K
  double t = 0.0;      // the quantile used
  std::vector<std::string> warnings;
};

// |correlation| above this: the two are hard to tell apart by these readings.
inline constexpr double correlation_limit = 0.9;

// J: d(model - reading) / d parameter (unweighted, K per unit), residuals
// at the optimum; noise: the thermometers' standard uncertainty, if known.
Intervals intervals(const std::vector<ParameterSpan>& parameters, const Eigen::MatrixXd& J,
                    const std::vector<double>& residuals, std::optional<double> noise);

// The intervals checked against the misfit itself, for what the Jacobian
// cannot see: the misfit's ripple (a sensor's reading moves in small steps
// as the particles round it freeze), and a valley flatter or more curved
// than its tangent. Along each principal axis of the covariance, both
// ways, the misfit should have risen by t^2 s^2 at t standard errors out;
// where it rose less, the axis is looked at again 2t and 4t out (each
// round one batch through ssr_at, which returns the sum of squared
// residuals at each point), and its standard error is stretched so that a
// misfit rising quadratically through the point looked at reaches t^2 s^2
// at the interval's end. Intervals only widen. `runs` counts the points.
inline constexpr int misfit_rounds = 3;
Intervals checked_by_misfit(const std::vector<ParameterSpan>& parameters, const Intervals& linear, double ssr_at_fit,
                            const std::function<std::vector<double>(const std::vector<std::vector<double>>&)>& ssr_at,
                            int* runs = nullptr);

// Student's t at 97.5 % for `dof` degrees of freedom (1.96 beyond 30).
double student_t975(int dof);

}  // namespace frostwall::calibrate
