// Ceres Solver against Eigen's Levenberg-Marquardt (unsupported module) on
// the same calibration: a twin on the scaled ring of the calibration checks
// (tests/data/calibrate_twin_ring.json), both conductivities x1.15 and the latent heat x0.9, 0.1 K of
// noise, readings every half day to day 20. Both get the same residuals
// and the same central-difference Jacobian, its 2n runs side by side; Eigen
// has no bounds (none is reached here). Prints the values, the misfit, the
// runs and the time of each (bench/README.md).
//
//   build/bench/calibrate_solvers
#include <chrono>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <random>
#include <unistd.h>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "calibrate/fit.hpp"
#include "calibrate/forward.hpp"
#include "calibrate/parameters.hpp"
#include "project/project.hpp"

using namespace frostwall;
namespace fs = std::filesystem;

namespace {

const std::vector<double> truth{1.15, 1.15, 0.9};

std::string project_text() {
  std::ifstream in(FROSTWALL_SOURCE_DIR "/tests/data/calibrate_twin_ring.json");
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

struct Twin {
  project::Project p;
  std::vector<double> measured;
  fs::path scratch;
  int runs = 0;
  std::vector<std::vector<double>> residuals(const std::vector<std::vector<double>>& points) {
    std::vector<std::function<calibrate::ForwardResult()>> tasks;
    for (const auto& x : points) {
      const fs::path dir = scratch / fmt::format("run{}", runs++);
      tasks.push_back([this, x, dir] {
        return calibrate::run_forward(calibrate::fit_project(p, x), p.calibration->readings, dir);
      });
    }
    std::vector<std::vector<double>> r;
    for (auto& f : calibrate::side_by_side(tasks, 2, 1)) {
      for (std::size_t k = 0; k < measured.size(); ++k) f.temperatures[k] -= measured[k];
      r.push_back(f.temperatures);
    }
    return r;
  }
};

// Eigen's functor: values by one run, the Jacobian by the same central
// differences as the Ceres fit (2n runs side by side).
struct EigenFunctor : Eigen::DenseFunctor<double> {
  Twin& twin;
  std::vector<double> step;
  EigenFunctor(Twin& t, int m, std::vector<double> h) : Eigen::DenseFunctor<double>(3, m), twin(t), step(h) {}
  int operator()(const InputType& x, ValueType& f) const {
    const auto r = twin.residuals({{x(0), x(1), x(2)}}).front();
    for (int i = 0; i < values(); ++i) f(i) = r[i];
    return 0;
  }
  int df(const InputType& x, JacobianType& J) const {
    std::vector<std::vector<double>> points;
    for (int j = 0; j < 3; ++j)
      for (double s : {1.0, -1.0}) {
        std::vector<double> y{x(0), x(1), x(2)};
        y[j] += s * step[j];
        points.push_back(y);
      }
    const auto r = twin.residuals(points);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < values(); ++i) J(i, j) = (r[2 * j][i] - r[2 * j + 1][i]) / (2 * step[j]);
    return 0;
  }
};

double rms(const std::vector<double>& r) {
  double s = 0;
  for (double v : r) s += v * v;
  return std::sqrt(s / r.size());
}

}  // namespace

int main() {
  const fs::path dir = fs::temp_directory_path() / fmt::format("frostwall-calibrate-solvers-{}", ::getpid());
  fs::create_directories(dir);
  {
    std::ofstream(dir / "readings.csv") << "sensor,time,temperature\n";
    std::string csv = "sensor,time,temperature\n";
    for (const char* s : {"neck", "outside", "inside"})
      for (int k = 1; k <= 40; ++k) csv += fmt::format("{},{:g},0\n", s, 0.5 * k);
    std::ofstream(dir / "readings.csv") << csv;
  }
  Twin twin{project::parse_project(project_text(), "bench", dir.string()), {}, dir / "runs"};
  twin.measured.assign(twin.p.calibration->readings.size(), 0.0);
  auto clean = twin.residuals({truth}).front();
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  for (std::size_t k = 0; k < clean.size(); ++k) twin.measured[k] = clean[k] + noise(rng);
  const std::vector<double> step{0.075, 0.075, 0.075};  // 5 % of the bounds, as frostwall calibrate
  fmt::print("twin: {} readings, truth {} {} {}\n", clean.size(), truth[0], truth[1], truth[2]);

  twin.runs = 0;
  auto t0 = std::chrono::steady_clock::now();
  calibrate::FitProblem problem;
  problem.start = {1, 1, 1};
  problem.low = {0.5, 0.5, 0.5};
  problem.high = {2, 2, 2};
  problem.step = step;
  problem.residual_count = clean.size();
  problem.residuals = [&](const std::vector<std::vector<double>>& x) { return twin.residuals(x); };
  const auto fit = calibrate::least_squares(problem);
  const double ceres_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("ceres: {:.4f} {:.4f} {:.4f}, rms {:.4f} K, {} iterations, {} runs, {:.1f} s ({})\n", fit.values[0],
             fit.values[1], fit.values[2], rms(fit.residuals), fit.iterations, twin.runs, ceres_s, fit.termination);

  twin.runs = 0;
  t0 = std::chrono::steady_clock::now();
  EigenFunctor functor(twin, static_cast<int>(clean.size()), step);
  Eigen::LevenbergMarquardt<EigenFunctor> lm(functor);
  lm.setFtol(1e-3);
  lm.setXtol(1e-3);
  Eigen::VectorXd x(3);
  x << 1, 1, 1;
  const auto status = lm.minimize(x);
  const double eigen_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto r = twin.residuals({{x(0), x(1), x(2)}}).front();
  fmt::print("eigen: {:.4f} {:.4f} {:.4f}, rms {:.4f} K, {} iterations, {} runs, {:.1f} s (status {})\n", x(0), x(1),
             x(2), rms(r), lm.iterations(), twin.runs - 1, eigen_s, static_cast<int>(status));
  fs::remove_all(dir);
}
