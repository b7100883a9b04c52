// Calibration from thermometers: the least-squares machinery against exact
// solutions (a linear model, where the fit and its covariance are known in
// closed form), then twin experiments on a scaled ring: readings made by
// frostwall itself from known parameters plus noise, which the fit must
// recover. Bad input last.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>

#include "calibrate/fit.hpp"
#include "calibrate/intervals.hpp"

using namespace frostwall;

namespace {

// y = a + b t + c t^2 sampled at t = 0..1, with Gaussian noise of a seed.
struct LinearTwin {
  std::vector<double> t, y;
  Eigen::MatrixXd A;
  LinearTwin(std::array<double, 3> truth, double noise, int m, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> e(0.0, noise);
    A.resize(m, 3);
    for (int i = 0; i < m; ++i) {
      const double ti = static_cast<double>(i) / (m - 1);
      t.push_back(ti);
      A(i, 0) = 1.0, A(i, 1) = ti, A(i, 2) = ti * ti;
      y.push_back(truth[0] + truth[1] * ti + truth[2] * ti * ti + e(rng));
    }
  }
  std::vector<double> residuals(const std::vector<double>& x) const {
    std::vector<double> r;
    for (std::size_t i = 0; i < t.size(); ++i) r.push_back(x[0] + x[1] * t[i] + x[2] * t[i] * t[i] - y[i]);
    return r;
  }
};

}  // namespace

TEST_CASE("Calibration fit: a linear model's least squares and covariance in closed form", "[calibrate]") {
  const LinearTwin twin({1.0, -2.0, 0.5}, 0.1, 60, 7);
  calibrate::FitProblem problem;
  problem.start = {0.0, 0.0, 0.0};
  problem.low = {-10, -10, -10};
  problem.high = {10, 10, 10};
  problem.step = {0.01, 0.01, 0.01};
  problem.residual_count = twin.t.size();
  problem.function_tolerance = 1e-12;
  problem.parameter_tolerance = 1e-10;
  int batches = 0;
  problem.residuals = [&](const std::vector<std::vector<double>>& points) {
    ++batches;
    std::vector<std::vector<double>> r;
    for (const auto& x : points) r.push_back(twin.residuals(x));
    return r;
  };
  const auto fit = calibrate::least_squares(problem);
  // The normal equations, solved directly.
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(twin.y.data(), twin.y.size());
  const Eigen::VectorXd exact = (twin.A.transpose() * twin.A).ldlt().solve(twin.A.transpose() * y);
  for (int j = 0; j < 3; ++j) CHECK(fit.values[j] == Approx(exact(j)).margin(1e-6));
  CHECK(fit.converged);
  CHECK((fit.jacobian - twin.A).cwiseAbs().maxCoeff() < 1e-8);
  // The covariance s^2 (A^T A)^-1, with the bounds far away (their prior negligible).
  std::vector<calibrate::ParameterSpan> spans;
  for (int j = 0; j < 3; ++j) spans.push_back({fmt::format("p{}", j), fit.values[j], -10, 10});
  const auto iv = calibrate::intervals(spans, fit.jacobian, fit.residuals, std::nullopt);
  double ssr = 0.0;
  for (double r : fit.residuals) ssr += r * r;
  const Eigen::MatrixXd C = ssr / (60 - 3) * (twin.A.transpose() * twin.A).inverse();
  for (int j = 0; j < 3; ++j) {
    CHECK(iv.sigma[j] == Approx(std::sqrt(C(j, j))).epsilon(1e-3));
    CHECK(iv.identified[j]);
  }
  CHECK(iv.correlation(1, 2) == Approx(C(1, 2) / std::sqrt(C(1, 1) * C(2, 2))).epsilon(1e-3));
  CHECK(iv.t == Approx(2.0025).margin(0.003));  // Student's t(57) at 97.5 %
}
