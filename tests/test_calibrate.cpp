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
#include <map>
#include <random>
#include <sstream>

#include "calibrate/fit.hpp"
#include "calibrate/forward.hpp"
#include "calibrate/intervals.hpp"
#include "calibrate/parameters.hpp"
#include "calibrate/run_calibrate.hpp"
#include "run/run_project.hpp"
#include "summary/summary.hpp"
#include "io/xml_escape.hpp"
#include "project/project.hpp"
#include "cli.hpp"
#include "report/mustache_view.hpp"
#include "report/report.hpp"
#include "report/templates.hpp"
#include "report_view_check.hpp"
#include "temp_dir.hpp"
#include "twin_inputs.hpp"
#include "paths.hpp"

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

TEST_CASE("Calibration intervals checked by the misfit: kept where it rises as the Jacobian says, stretched where "
          "it rises less, to where it reaches t^2 s^2",
          "[calibrate]") {
  // Two correlated parameters, 60 readings; residuals of the noise's size.
  const std::vector<calibrate::ParameterSpan> spans{{"a", 1.0, -50.0, 50.0}, {"b", 2.0, -50.0, 50.0}};
  Eigen::MatrixXd J(60, 2);
  std::vector<double> residuals(60);
  for (int i = 0; i < 60; ++i) {
    J(i, 0) = 1.0 + 0.1 * i;
    J(i, 1) = 0.9 + 0.1 * i + 0.3 * std::sin(i);
    residuals[i] = 0.1 * ((i % 2) ? 1.0 : -1.0);
  }
  const calibrate::Intervals linear = calibrate::intervals(spans, J, residuals, 0.1);
  const Eigen::Vector2d x0(1.0, 2.0);
  const double ssr0 = 0.6;
  for (const double flatter : {1.0, 4.0, 64.0}) {
    // The misfit rising `flatter` times more slowly than J^T J says.
    auto ssr_at = [&](const std::vector<std::vector<double>>& points) {
      std::vector<double> out;
      for (const auto& p : points) {
        const Eigen::Vector2d d = Eigen::Vector2d(p[0], p[1]) - x0;
        out.push_back(ssr0 + (J * d).squaredNorm() / flatter);
      }
      return out;
    };
    int runs = 0;
    const auto checked = calibrate::checked_by_misfit(spans, linear, ssr0, ssr_at, &runs);
    INFO("flatter " << flatter << ", runs " << runs);
    for (int j = 0; j < 2; ++j) CHECK(checked.sigma[j] == Approx(linear.sigma[j] * std::sqrt(flatter)).epsilon(1e-3));
    CHECK(checked.correlation(0, 1) == Approx(linear.correlation(0, 1)).epsilon(1e-6));
    CHECK(runs == (flatter == 1.0 ? 4 : flatter == 4.0 ? 8 : 12));
  }
}

// ---- twin experiments on a scaled ring ---------------------------------------
//
// tests/data/calibrate_twin_ring.json: 8 pipes on a 1.55 m ring, the single
// ring's pipe spacing (1.2 m), so the columns close near the same day
// (12.6 d), on 1700 particles. Sensors: the neck between two pipes, and
// 0.5 m outside and inside the ring on the line through a pipe.

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// tests/data/calibrate_twin_ring.json with `parameters` to fit.
json twin_ring(const json& parameters) {
  json p = json::parse(std::ifstream(std::string(FROSTWALL_SOURCE_DIR) + "/tests/data/calibrate_twin_ring.json"));
  p["calibrate"]["parameters"] = parameters;
  return p;
}

const json three_factors = {
    {"conductivity_frozen", {0.5, 2.0}}, {"conductivity_unfrozen", {0.5, 2.0}}, {"latent_heat", {0.5, 2.0}}};
// conductivity_frozen, _unfrozen, latent_heat of the twin ground
const std::vector<double> truth{0.88, 1.10, 1.08};

// The project as `frostwall run` runs it with the twin ground: sand's
// values times `values` (the three factors above); its summary.
json run_twin(const json& project, const std::vector<double>& values, const fs::path& out) {
  json twin = project;
  twin.erase("calibrate");
  twin["soil"] = test::scaled_sand(values[0], values[1], values[2]);
  auto p = project::parse_project(twin.dump(), "twin", out.string());
  p.output.directory = (out / "out").string();
  return json::parse(summary::to_json(run::run_project(p, {})).dump());
}

// The readings of a twin: `frostwall run`'s monitoring of the twin ground
// (every sample, 200 over the run) to `until`, with 0.1 K of Gaussian noise
// of a fixed seed; `stop`: a sensor's last day.
std::string twin_readings(const json& project, const std::vector<double>& values, double until,
                          std::map<std::string, double> stop = {}) {
  test::TempDir dir("frostwall-twin");
  const json summary = run_twin(project, values, dir.path);
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 0.1);
  std::string csv = "sensor,time,temperature\n";
  for (const auto& sensor : project["monitoring"]) {
    const std::string name = sensor["name"];
    for (const auto& row : summary["monitoring"][name]) {
      const double day = row[0].get<double>();
      if (day <= (stop.count(name) ? stop[name] : until) + 1e-9)
        csv += fmt::format("{},{:.9g},{:.4f}\n", name, day, row[1].get<double>() + noise(rng));
    }
  }
  return csv;
}

// Calibrates `project` against `readings` in a fresh folder; the summary.
json calibrate_in(const json& project, const std::string& readings) {
  test::TempDir dir("frostwall-calibrate");
  std::ofstream(dir.path / "readings.csv") << readings;
  auto p = project::parse_project(project.dump(), "twin", dir.path.string());
  p.output.directory = (dir.path / "out").string();
  calibrate::CalibrateOptions o;
  o.project_text = project.dump();
  const auto s = calibrate::run_calibration(p, o);
  return json::parse(s.dump());
}

}  // namespace

TEST_CASE("Calibration twin: readings of `frostwall run` with frozen conductivity x0.88, unfrozen x1.10 and latent "
          "heat x1.08 recovered from three sensors to day 20, the band holding its closure",
          "[calibrate]") {
  const json project = twin_ring(three_factors);
  const json c = calibrate_in(project, twin_readings(project, truth, 20.0))["calibration"];
  INFO(c.dump(1));
  const char* names[] = {"conductivity_frozen", "conductivity_unfrozen", "latent_heat"};
  for (int j = 0; j < 3; ++j) {
    const auto& q = c["parameters"][names[j]];
    CHECK(q["value"].get<double>() == Approx(truth[j]).epsilon(0.03));
    CHECK(q["low"].get<double>() <= truth[j]);
    CHECK(q["high"].get<double>() >= truth[j]);
    CHECK(q["identified"].get<bool>());
  }
  // The misfit after the fit is the noise's (0.1 K), not the start's.
  CHECK(c["rms_misfit_after"].get<double>() < 0.12);
  CHECK(c["rms_misfit_before"].get<double>() > 3 * c["rms_misfit_after"].get<double>());
  // The forecast's band holds the twin's own closure.
  test::TempDir dir("frostwall-truth");
  const double true_closure = run_twin(project, truth, dir.path)["closure_time_days"].get<double>();
  CHECK(c["forecast"]["closure_day"]["low"].get<double>() <= true_closure);
  CHECK(c["forecast"]["closure_day"]["high"].get<double>() >= true_closure);
}

TEST_CASE("Calibration twin: readings to day 8, before closure, give a forecast band that covers the true closure",
          "[calibrate]") {
  const json project = twin_ring(three_factors);
  const json summary = calibrate_in(project, twin_readings(project, truth, 8.0));
  const json& band = summary["calibration"]["forecast"]["closure_day"];
  INFO(summary["calibration"].dump(1));
  // The truth: the twin as `frostwall run` runs it.
  test::TempDir dir("frostwall-truth");
  const double true_closure = run_twin(project, truth, dir.path)["closure_time_days"].get<double>();
  CHECK(summary["calibration"]["last_reading_day"].get<double>() < true_closure);
  CHECK(band["low"].get<double>() <= true_closure);
  CHECK(band["high"].get<double>() >= true_closure);
  // A band, not a point: the parameters' share is there.
  CHECK(band["parameter_spread"].get<double>() > 0.0);
  CHECK(band["value"].get<double>() == summary["closure_time_days"].get<double>());
}

TEST_CASE("Calibration twin: readings before any sensor freezes say the frozen conductivity is not told apart",
          "[calibrate]") {
  const json project = twin_ring(three_factors);
  const std::string readings = twin_readings(project, truth, 6.0);
  // No sensor has frozen by then (each stays above 0.5 degC).
  std::istringstream in(readings);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) REQUIRE(std::stod(line.substr(line.rfind(',') + 1)) > 0.5);
  const json c = calibrate_in(project, readings)["calibration"];
  INFO(c.dump(1));
  bool said = false;
  for (const auto& w : c["warnings"])
    said = said || w.get<std::string>().find("conductivity_frozen") != std::string::npos;
  CHECK(said);
  CHECK((!c["parameters"]["conductivity_frozen"]["identified"].get<bool>() ||
         std::abs(c["correlation"]["matrix"][0][2].get<double>()) > calibrate::correlation_limit));
}

TEST_CASE("Calibration twin: a sensor that stops halfway still lets the fit converge (frostwall calibrate, report)",
          "[calibrate]") {
  json project = twin_ring(three_factors);
  project["output"]["report"] = true;
  test::TempDir dir("frostwall-calibrate-cli");
  std::ofstream(dir.path / "p.json") << project.dump(2);
  std::ofstream(dir.path / "readings.csv") << twin_readings(project, truth, 20.0, {{"inside", 10.0}});
  test::require_frostwall(dir.path, "calibrate p.json");
  const fs::path out = dir.path / "out";
  const json summary = json::parse(std::ifstream(out / "summary.json"));
  const json& c = summary["calibration"];
  INFO(c.dump(1));
  CHECK(c["converged"].get<bool>());
  CHECK(c["reading_count"].get<int>() == 100 + 100 + 50);
  CHECK(c["parameters"]["latent_heat"]["value"].get<double>() == Approx(truth[2]).epsilon(0.03));
  CHECK(c["rms_misfit_after"].get<double>() < 0.12);
  // The calibrated project file runs as calibrated: the sand's values times the fitted factors.
  const auto calibrated = project::load_project((out / "calibrated.json").string());
  const auto sand = *project::builtin_soil("sand");
  CHECK(calibrated.soil.latent_heat ==
        Approx(sand.latent_heat * c["parameters"]["latent_heat"]["value"].get<double>()).epsilon(1e-12));
  CHECK(calibrated.soil.frozen.conductivity[0] ==
        Approx(sand.frozen.conductivity[0] * c["parameters"]["conductivity_frozen"]["value"].get<double>())
            .epsilon(1e-12));
  CHECK(!calibrated.calibration);
  // The report's calibration section: every name it uses in the view, one
  // chart per sensor, the table, the forecast.
  const json view = report::report_view(out);
  const auto block = test::split_section(report::templates::report_html, "has_calibration").first;
  for (const auto& name : report::template_names(block)) {
    INFO(name);
    CHECK(test::has_key(view, name));
  }
  std::ifstream in(out / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // Each warning of the fit (the frozen conductivity and the latent heat
  // are correlated above 0.9 on these readings) is in the report too.
  REQUIRE(!c["warnings"].empty());
  for (const auto& w : c["warnings"]) CHECK_THAT(html, Catch::Contains(io::xml_escape(w.get<std::string>())));
  CHECK_THAT(html, Catch::Contains("Calibration from the thermometers"));
  for (const char* sensor : {"neck", "outside", "inside"})
    CHECK_THAT(html, Catch::Contains(fmt::format("sensor {}: measured and simulated", sensor)));
  CHECK_THAT(html, Catch::Contains("95 % interval"));
  CHECK(fs::exists(out / "calibration.csv"));
  CHECK(fs::exists(out / "calibration_fit.csv"));
}

TEST_CASE("Calibration bad input: one line naming the file and line or the JSON path, status 2, nothing written",
          "[calibrate][bad_input]") {
  const std::string good = "sensor,time,temperature\nneck,1,10\nneck,2,8\noutside,1,12\ninside,2,9\n";
  struct Case {
    const char* what;
    std::function<void(json&)> edit;
    std::string readings;
    const char* expected;
  };
  const std::vector<Case> cases{
      {"a sensor outside the domain", [](json& p) { p["monitoring"][1]["r"] = 6.0; }, good,
       "monitoring[1]: r = 6 m is outside the simulated domain"},
      {"a sensor inside a pipe", [](json& p) { p["monitoring"][1]["r"] = 1.58; }, good,
       "monitoring[1]: sensor 'outside' at (1.58, 0) m is inside pipe 1"},
      {"readings after the run's end", [](json&) {}, good + "neck,41,-9\n",
       "calibrate.readings: readings.csv line 6: time 41 is after the run's end (time.end 40 d)"},
      {"a non-numeric cell", [](json&) {}, good + "neck,5,cold\n",
       "calibrate.readings: readings.csv line 6: temperature 'cold' is not a number"},
      {"an unknown sensor", [](json&) {}, good + "probe,5,1\n",
       "calibrate.readings: readings.csv line 6: sensor 'probe' is not in \"monitoring\""},
      {"an unknown parameter",
       [](json& p) {
         p["calibrate"]["parameters"]["porosity"] = {0.1, 0.4};
       },
       good, "calibrate.parameters.porosity: unknown parameter 'porosity'"},
      {"bounds that exclude the start value",
       [](json& p) {
         p["calibrate"]["parameters"]["latent_heat"] = {1.1, 2.0};
       },
       good, "calibrate.parameters.latent_heat: bounds [1.1, 2] exclude the start value 1"},
      {"fewer readings than parameters", [](json&) {}, "sensor,time,temperature\nneck,1,10\nneck,2,8\n",
       "calibrate.readings: readings.csv: 2 readings cannot fit 3 parameters"},
  };
  for (const auto& c : cases) {
    SECTION(c.what) {
      test::TempDir dir("frostwall-calibrate-bad");
      json project = twin_ring(three_factors);
      c.edit(project);
      std::ofstream(dir.path / "p.json") << project.dump(2);
      std::ofstream(dir.path / "readings.csv") << c.readings;
      const auto run = test::frostwall_cli(dir.path, "calibrate p.json");
      CHECK(run.exit_status == 2);
      REQUIRE(run.stderr_lines.size() == 1);
      CHECK_THAT(run.stderr_lines[0], Catch::Contains(c.expected));
      CHECK(!fs::exists(dir.path / "out"));
    }
  }
}
