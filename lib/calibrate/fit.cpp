#include "calibrate/fit.hpp"

#include <ceres/ceres.h>
#include <fmt/format.h>
#include <array>
#include <map>
#include <mutex>

namespace frostwall::calibrate {

namespace {

// The residuals of every point run so far, keyed by the exact parameters.
class RunMemory {
 public:
  explicit RunMemory(const FitProblem& problem) : problem_(problem) {}

  // The residuals at each point; the points not run before run as one batch.
  std::vector<std::vector<double>> at(const std::vector<std::vector<double>>& points) {
    std::vector<std::vector<double>> fresh;
    for (const auto& x : points)
      if (!runs_.count(x) && std::find(fresh.begin(), fresh.end(), x) == fresh.end()) fresh.push_back(x);
    if (!fresh.empty()) {
      const auto values = problem_.residuals(fresh);
      for (std::size_t k = 0; k < fresh.size(); ++k) runs_[fresh[k]] = values.at(k);
    }
    std::vector<std::vector<double>> out;
    for (const auto& x : points) out.push_back(runs_.at(x));
    return out;
  }
  int count() const { return static_cast<int>(runs_.size()); }

 private:
  const FitProblem& problem_;
  std::map<std::vector<double>, std::vector<double>> runs_;
};

// The points of a central-difference Jacobian at x: x itself, then x
// moved by each parameter's step up and down (one-sided, inwards, where a
// step would leave the bounds). `offsets` gets each point's move.
std::vector<std::vector<double>> jacobian_points(const FitProblem& p, const std::vector<double>& x,
                                                 std::vector<std::array<double, 2>>& offsets) {
  std::vector<std::vector<double>> points{x};
  offsets.assign(x.size(), {0.0, 0.0});
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double h = p.step[j];
    const bool up = x[j] + h <= p.high[j], down = x[j] - h >= p.low[j];
    offsets[j] = up && down ? std::array{h, -h} : (up ? std::array{h, 0.0} : std::array{0.0, -h});
    for (const double d : offsets[j]) {
      auto moved = x;
      moved[j] += d;
      points.push_back(moved);
    }
  }
  return points;
}

Eigen::MatrixXd jacobian_of(const std::vector<std::vector<double>>& r,
                            const std::vector<std::array<double, 2>>& offsets) {
  const std::size_t m = r.front().size(), n = offsets.size();
  Eigen::MatrixXd J(m, n);
  for (std::size_t j = 0; j < n; ++j) {
    const auto& a = r[1 + 2 * j];
    const auto& b = r[2 + 2 * j];
    for (std::size_t i = 0; i < m; ++i) J(i, j) = (a[i] - b[i]) / (offsets[j][0] - offsets[j][1]);
  }
  return J;
}

class BatchCost : public ceres::CostFunction {
 public:
  BatchCost(const FitProblem& p, RunMemory& memory) : p_(p), memory_(memory) {
    set_num_residuals(static_cast<int>(p.residual_count));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(p.start.size()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const std::vector<double> x(parameters[0], parameters[0] + p_.start.size());
    std::vector<std::array<double, 2>> steps;
    const bool with_jacobian = jacobians && jacobians[0];
    const auto r = memory_.at(with_jacobian ? jacobian_points(p_, x, steps) : std::vector<std::vector<double>>{x});
    for (double v : r[0])
      if (!std::isfinite(v)) return false;  // the solver then shortens its step
    std::copy(r[0].begin(), r[0].end(), residuals);
    if (with_jacobian) {
      const Eigen::MatrixXd J = jacobian_of(r, steps);
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(jacobians[0], J.rows(),
                                                                                         J.cols()) = J;
    }
    return true;
  }

 private:
  const FitProblem& p_;
  RunMemory& memory_;
};

class Progress : public ceres::IterationCallback {
 public:
  Progress(const FitProblem& p, const RunMemory& memory, const std::vector<double>& x)
      : p_(p), memory_(memory), x_(x) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    rejected_ = s.iteration > 0 && !s.step_is_successful ? rejected_ + 1 : 0;
    if (p_.note) {
      std::string values;
      for (double v : x_) values += fmt::format(" {:.4g}", v);
      p_.note(rejected_ > 0 ? fmt::format("  iteration {:2d}: step rejected ({} runs)", s.iteration, memory_.count())
                            : fmt::format("  iteration {:2d}: rms misfit {:.4g} K, parameters{} ({} runs)", s.iteration,
                                          std::sqrt(2.0 * s.cost / static_cast<double>(p_.residual_count)), values,
                                          memory_.count()));
    }
    // Steps rejected in a row: the trust region has shrunk to the misfit's
    // ripple, below which no step can be told from another.
    if (rejected_ >= max_rejected) {
      stopped_ = true;
      return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    }
    return ceres::SOLVER_CONTINUE;
  }
  bool stopped() const { return stopped_; }
  static constexpr int max_rejected = 3;

 private:
  const FitProblem& p_;
  const RunMemory& memory_;
  const std::vector<double>& x_;
  int rejected_ = 0;
  bool stopped_ = false;
};

}  // namespace

FitResult least_squares(const FitProblem& problem) {
  const std::size_t n = problem.start.size();
  RunMemory memory(problem);
  std::vector<double> x = problem.start;
  ceres::Problem solver_problem;
  solver_problem.AddResidualBlock(new BatchCost(problem, memory), nullptr, x.data());
  for (std::size_t j = 0; j < n; ++j) {
    solver_problem.SetParameterLowerBound(x.data(), static_cast<int>(j), problem.low[j]);
    solver_problem.SetParameterUpperBound(x.data(), static_cast<int>(j), problem.high[j]);
  }
  ceres::Solver::Options options;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = problem.max_iterations;
  options.function_tolerance = problem.function_tolerance;
  options.parameter_tolerance = problem.parameter_tolerance;
  // No projected line search after a rejected step at a bound: each of its
  // points would cost a Jacobian (a batch of runs).
  options.max_num_line_search_step_size_iterations = 0;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;  // the forward runs take the cores
  Progress progress(problem, memory, x);
  options.callbacks.push_back(&progress);
  options.update_state_every_iteration = true;
  ceres::Solver::Summary summary;
  FitResult result;
  result.start_residuals = memory.at({problem.start}).front();
  ceres::Solve(options, &solver_problem, &summary);
  result.values = x;
  std::vector<std::array<double, 2>> steps;
  const auto r = memory.at(jacobian_points(problem, x, steps));
  result.residuals = r.front();
  result.jacobian = jacobian_of(r, steps);
  result.iterations = static_cast<int>(summary.iterations.size()) - 1;
  result.forward_runs = memory.count();
  result.converged = summary.termination_type == ceres::CONVERGENCE || progress.stopped();
  result.termination = progress.stopped() ? fmt::format("{} steps rejected in a row: the misfit's ripple reached",
                                                        Progress::max_rejected)
                                          : summary.message;
  return result;
}

}  // namespace frostwall::calibrate
