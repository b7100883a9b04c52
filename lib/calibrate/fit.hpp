// Bounded nonlinear least squares for a forward model that is a whole
// simulation: Ceres Solver's Levenberg-Marquardt trust region, with the
// Jacobian by central differences whose runs go side by side (one batch
// per Jacobian), every run remembered so that no point is run twice.
//
// The steps are wide on purpose. A simulated sensor's temperature ripples
// with the parameters on a small scale (each particle that freezes is a
// step in time), so a narrow difference measures the ripple and its
// gradient can point away from the truth (bench/README.md, "Calibration
// from thermometers"). A central difference over a few per cent of the
// bounds sees the trend, without the forward difference's bias from the
// curvature.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <string>
#include <vector>

namespace frostwall::calibrate {

struct FitProblem {
  std::vector<double> start, low, high;
  // Central-difference half step per parameter (one-sided at a bound).
  std::vector<double> step;
  std::size_t residual_count = 0;
  // The residual vectors at several points at once (a batch of runs).
  std::function<std::vector<std::vector<double>>(const std::vector<std::vector<double>>&)> residuals;
  int max_iterations = 25;
  // The fit ends when an iteration changes the misfit (sum of squares) by
  // less than this fraction, or the parameters by less than
  // parameter_tolerance of their size: finer than that, the misfit's ripple
  // decides.
  double function_tolerance = 1e-3;
  double parameter_tolerance = 1e-3;
  // Called after each iteration with a one-line account of it; may be empty.
  std::function<void(const std::string&)> note;
};

struct FitResult {
  std::vector<double> values;
  std::vector<double> residuals;  // at values
  Eigen::MatrixXd jacobian;       // d residual / d parameter at values (residual_count x parameters)
  std::vector<double> start_residuals;
  int iterations = 0;
  int forward_runs = 0;
  bool converged = false;
  std::string termination;  // the solver's own account
};

FitResult least_squares(const FitProblem& problem);

}  // namespace frostwall::calibrate
