#include "calibrate/run_calibrate.hpp"

#include <algorithm>
#include <ceres/version.h>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <numeric>

#include "calibrate/fit.hpp"
#include "calibrate/forecast.hpp"
#include "calibrate/forward.hpp"
#include "calibrate/intervals.hpp"
#include "particles/side_by_side.hpp"
#include "calibrate/parameters.hpp"
#include "freezing/heat_run.hpp"
#include "geometry/layout.hpp"
#include "io/atomic_file.hpp"
#include "project/units.hpp"
#include "io/summary_file.hpp"
#include "run/run_project.hpp"

namespace frostwall::calibrate {

namespace fs = std::filesystem;
using project::Project;
using project::ProjectError;

namespace {

// Forward runs at once and threads each: the cores shared among the jobs.
std::pair<int, int> share_cores(const CalibrateOptions& o, std::size_t runs) {
  const int cores = particles::usable_cores();
  const int jobs = std::clamp(o.jobs > 0 ? o.jobs : cores, 1, std::max<int>(1, static_cast<int>(runs)));
  const int threads = o.threads > 0 ? o.threads : std::max(1, cores / jobs);
  return {jobs, threads};
}

std::vector<ForwardResult> run_batch(const std::vector<std::function<ForwardResult()>>& tasks,
                                     const CalibrateOptions& o) {
  const auto [jobs, threads] = share_cores(o, tasks.size());
  return side_by_side(tasks, jobs, threads);
}

double rms(const std::vector<double>& r) {
  double s = 0.0;
  for (double v : r) s += v * v;
  return r.empty() ? 0.0 : std::sqrt(s / static_cast<double>(r.size()));
}

std::string fit_csv(const Project& p, const std::vector<double>& start, const std::vector<double>& fitted) {
  const auto& c = *p.calibration;
  const double unit = p.time.unit_seconds();
  std::string csv = "sensor,time,measured_C,start_C,fitted_C\n";
  for (std::size_t k = 0; k < c.readings.size(); ++k) {
    const auto& r = c.readings[k];
    csv += fmt::format("{},{:.6g},{:.6g},{:.6g},{:.6g}\n", r.plant_return ? "return" : p.monitoring[r.sensor].name,
                       r.time / unit, r.temperature, r.temperature + start[k], r.temperature + fitted[k]);
  }
  return csv;
}

nlohmann::ordered_json parameters_json(const Project& p, const FitResult& fit, const Intervals& iv) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  const auto& params = p.calibration->parameters;
  for (std::size_t j = 0; j < params.size(); ++j)
    out[project::parameter_name(params[j].which)] = {{"value", fit.values[j]},
                                                     {"low", iv.low[j]},
                                                     {"high", iv.high[j]},
                                                     {"sigma", iv.sigma[j]},
                                                     {"start", params[j].start},
                                                     {"bounds", {params[j].low, params[j].high}},
                                                     {"unit", parameter_unit(params[j].which)},
                                                     {"identified", static_cast<bool>(iv.identified[j])}};
  return out;
}

std::string parameters_csv(const Project& p, const FitResult& fit, const Intervals& iv) {
  std::string csv = "parameter,unit,start,value,low,high,sigma,bound_low,bound_high,identified\n";
  const auto& params = p.calibration->parameters;
  for (std::size_t j = 0; j < params.size(); ++j)
    csv += fmt::format("{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.4g},{:.6g},{:.6g},{}\n",
                       project::parameter_name(params[j].which), parameter_unit(params[j].which), params[j].start,
                       fit.values[j], iv.low[j], iv.high[j], iv.sigma[j], params[j].low, params[j].high,
                       iv.identified[j] ? "yes" : "no");
  return csv;
}

// The runs behind the forecast's band: parameter j moved by its standard
// error (inwards at a bound), each to the run's end.
std::vector<double> band_steps(const Project& p, const FitResult& fit, const Intervals& iv) {
  std::vector<double> steps;
  const auto& params = p.calibration->parameters;
  for (std::size_t j = 0; j < params.size(); ++j) {
    const double s = std::max(iv.sigma[j], 1e-3 * (params[j].high - params[j].low));
    steps.push_back(fit.values[j] + s <= params[j].high ? s : -std::min(s, fit.values[j] - params[j].low));
  }
  return steps;
}

}  // namespace

void check_calibration(const Project& p) {
  if (!p.calibration)
    throw ProjectError({R"(calibrate: required for `frostwall calibrate` ({"readings": "file.csv", "parameters": )"
                        R"({"latent_heat": [0.5, 2.0], ...}}))"});
  const auto& section = std::get<project::ShaftSection>(p.geometry);
  std::vector<std::string> problems;
  if (project::has_wall(section.pipe.model))
    for (std::size_t s = 0; s < p.monitoring.size(); ++s)
      for (const auto& pipe : geometry::pipe_positions(section.layout))
        if (std::hypot(p.monitoring[s].x - pipe.x, p.monitoring[s].y - pipe.y) < 0.5 * section.pipe.diameter)
          problems.push_back(fmt::format("monitoring[{}]: sensor '{}' at ({:g}, {:g}) m is inside pipe {} (a "
                                         "thermometer in the ground reads the ground)",
                                         s, p.monitoring[s].name, p.monitoring[s].x, p.monitoring[s].y, pipe.number));
  if (!problems.empty()) throw ProjectError(problems);
  freezing::check_run_inputs(p);
}

std::string describe_calibration(const Project& p) {
  const auto& c = *p.calibration;
  double last = 0.0;
  for (const auto& r : c.readings) last = std::max(last, r.time);
  std::string names;
  for (const auto& q : c.parameters)
    names += (names.empty() ? "" : ", ") + std::string(project::parameter_name(q.which));
  const bool plant_return =
      std::any_of(c.readings.begin(), c.readings.end(), [](const auto& r) { return r.plant_return; });
  return fmt::format("calibrate: {} readings of {} sensors{} to {:g} {} ({}); fits {} (`frostwall calibrate`)",
                     c.readings.size(), p.monitoring.size(), plant_return ? " and the plant's return" : "",
                     last / p.time.unit_seconds(), p.time.unit_name(), c.file, names);
}

namespace {

// One calibration: its project and options, the readings, the cloud every
// run copies, and the folder its runs write into and leave.
struct Context {
  const Project& p;
  const CalibrateOptions& options;
  fs::path out, scratch;
  double last = 0.0;             // the last reading, s
  std::vector<double> measured;  // degC, in the readings' order
  freezing::Model cloud;         // placed once: the parameters change the ground, not its geometry
  std::size_t run_number = 0;
  std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now();

  Context(const Project& project, const CalibrateOptions& o)
      : p(project), options(o), out(p.output.directory), scratch(out / ".calibration-runs") {
    for (const auto& r : p.calibration->readings) last = std::max(last, r.time), measured.push_back(r.temperature);
    cloud = freezing::build_cloud(p);
  }
  void note(const std::string& s) const {
    if (options.note) options.note(s);
  }
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); }
};

// The residuals (simulated - measured) at several points, their runs side
// by side.
std::vector<std::vector<double>> residuals_at(Context& ctx, const std::vector<std::vector<double>>& points) {
  const auto& c = *ctx.p.calibration;
  std::vector<std::function<ForwardResult()>> tasks;
  for (const auto& x : points) {
    const fs::path dir = ctx.scratch / fmt::format("run{}", ctx.run_number++);
    tasks.push_back([&ctx, &c, x, dir] { return run_forward(fit_project(ctx.p, x), c.readings, dir, &ctx.cloud); });
  }
  std::vector<std::vector<double>> r;
  for (auto& result : run_batch(tasks, ctx.options)) {
    for (std::size_t k = 0; k < result.temperatures.size(); ++k) result.temperatures[k] -= ctx.measured[k];
    r.push_back(std::move(result.temperatures));
  }
  fs::remove_all(ctx.scratch);
  return r;
}

// The least-squares fit of the readings, each batch of runs side by side.
FitResult fit_readings(Context& ctx) {
  const auto& c = *ctx.p.calibration;
  FitProblem problem;
  for (const auto& q : c.parameters) {
    problem.start.push_back(q.start);
    problem.low.push_back(q.low);
    problem.high.push_back(q.high);
    problem.step.push_back(0.05 * (q.high - q.low));
  }
  problem.residual_count = c.readings.size();
  problem.residuals = [&ctx](const std::vector<std::vector<double>>& points) { return residuals_at(ctx, points); };
  problem.note = ctx.options.note;
  const auto [jobs, threads] = share_cores(ctx.options, c.parameters.size());
  ctx.note(fmt::format("calibrate: {} readings to day {:g}, {} parameters; forward runs {} at a time on {} thread{}",
                       c.readings.size(), ctx.last / project::seconds_per_day, c.parameters.size(), jobs, threads,
                       threads > 1 ? "s" : ""));
  return least_squares(problem);
}

// The intervals from the Jacobian at the optimum, then checked against the
// misfit along their axes.
Intervals fit_intervals(Context& ctx, const FitResult& fit, int& runs) {
  const auto& c = *ctx.p.calibration;
  std::vector<ParameterSpan> spans;
  for (std::size_t j = 0; j < c.parameters.size(); ++j)
    spans.push_back(
        {project::parameter_name(c.parameters[j].which), fit.values[j], c.parameters[j].low, c.parameters[j].high});
  const Intervals linear = intervals(spans, fit.jacobian, fit.residuals, c.noise);
  auto ssr_at = [&ctx](const std::vector<std::vector<double>>& points) {
    std::vector<double> out;
    for (const auto& r : residuals_at(ctx, points))
      out.push_back(std::inner_product(r.begin(), r.end(), r.begin(), 0.0));
    return out;
  };
  const double ssr = std::inner_product(fit.residuals.begin(), fit.residuals.end(), fit.residuals.begin(), 0.0);
  return checked_by_misfit(spans, linear, ssr, ssr_at, &runs);
}

struct ForecastRuns {
  std::string calibrated_text;         // the calibrated project file (empty without the project's text)
  double design_time = 0.0;            // s
  std::vector<double> steps;           // each parameter's move in the band's runs
  summary::Summary calibrated;         // the calibrated run's, with its error bars
  std::vector<summary::Summary> band;  // the band's runs' summaries: the fitted values, then one per move
};

// The calibrated project as `frostwall run` runs it, with its error bar,
// into the output directory; then the band's runs: the calibrated values
// and each parameter moved by its standard error, at the fit's step
// control (a smooth response).
ForecastRuns run_forecast(Context& ctx, const FitResult& fit, const Intervals& iv) {
  const auto& c = *ctx.p.calibration;
  ForecastRuns f;
  Project fitted = with_values(ctx.p, c.parameters, fit.values);
  f.design_time = c.design_time.value_or(ctx.p.time.end);
  auto& snaps = fitted.time.snapshots;
  if (std::none_of(snaps.begin(), snaps.end(), [&](double s) { return std::abs(s - f.design_time) <= 1e-9 * s; })) {
    snaps.push_back(f.design_time);
    std::sort(snaps.begin(), snaps.end());
  }
  fitted.numerics.error_estimate = true;
  if (!ctx.options.project_text.empty()) f.calibrated_text = calibrated_project_text(ctx.options.project_text, fitted);
  ctx.note("calibrate: the calibrated run, with its error estimate");
  project::RunOptions run_options;
  run_options.project_text = f.calibrated_text;
  run_options.progress = ctx.options.progress;
  f.calibrated = run::run_project(fitted, run_options);
  f.steps = band_steps(ctx.p, fit, iv);
  std::vector<std::function<ForwardResult()>> tasks;
  for (std::size_t j = 0; j <= f.steps.size(); ++j) {
    auto x = fit.values;
    if (j > 0) x[j - 1] += f.steps[j - 1];
    Project moved = fit_project(ctx.p, x);
    moved.time.snapshots = fitted.time.snapshots;
    const fs::path dir = ctx.scratch / fmt::format("band{}", j);
    tasks.push_back([moved, dir, &ctx] { return run_forward(moved, {}, dir, &ctx.cloud); });
  }
  ctx.note(fmt::format("calibrate: {} runs for the forecast's band", tasks.size()));
  for (auto& r : run_batch(tasks, ctx.options)) f.band.push_back(std::move(r.summary));
  fs::remove_all(ctx.scratch);
  return f;
}

// summary.json's "calibration" block.
nlohmann::ordered_json calibration_json(const Context& ctx, const FitResult& fit, const Intervals& iv,
                                        const Forecast& f, double fit_seconds) {
  const auto& c = *ctx.p.calibration;
  std::vector<std::string> names, sensors;
  for (const auto& q : c.parameters) names.push_back(project::parameter_name(q.which));
  for (const auto& s : ctx.p.monitoring) sensors.push_back(s.name);
  if (std::any_of(c.readings.begin(), c.readings.end(), [](const auto& r) { return r.plant_return; }))
    sensors.push_back("return");
  std::vector<std::vector<double>> correlation(names.size());
  for (Eigen::Index i = 0; i < iv.correlation.rows(); ++i)
    for (Eigen::Index j = 0; j < iv.correlation.cols(); ++j) correlation[i].push_back(iv.correlation(i, j));
  return {
      {"readings", c.file},
      {"reading_count", c.readings.size()},
      {"last_reading_day", ctx.last / project::seconds_per_day},
      {"sensors", sensors},
      {"parameters", parameters_json(ctx.p, fit, iv)},
      {"correlation", {{"parameters", names}, {"matrix", correlation}}},
      {"rms_misfit_before", rms(fit.start_residuals)},
      {"rms_misfit_after", rms(fit.residuals)},
      {"noise", iv.noise},
      {"noise_given", c.noise.has_value()},
      {"t_quantile", iv.t},
      {"warnings", iv.warnings},
      {"iterations", fit.iterations},
      {"forward_runs", fit.forward_runs},
      {"converged", fit.converged},
      {"solver", "Ceres Solver " CERES_VERSION_STRING ", Levenberg-Marquardt, bounded; " + fit.termination},
      {"fit_seconds", fit_seconds},
      {"seconds", ctx.seconds()},
      {"forecast", forecast_json(f)},
      {"calibrated_project", "calibrated.json"},
  };
}

}  // namespace

nlohmann::ordered_json run_calibration(const Project& p, const CalibrateOptions& options) {
  check_calibration(p);
  Context ctx(p, options);
  FitResult fit = fit_readings(ctx);
  ctx.note(fmt::format("calibrate: rms misfit {:.3g} K before, {:.3g} K after ({} iterations, {} runs, {:.1f} s)",
                       rms(fit.start_residuals), rms(fit.residuals), fit.iterations, fit.forward_runs, ctx.seconds()));
  int check_runs = 0;
  const Intervals iv = fit_intervals(ctx, fit, check_runs);
  fit.forward_runs += check_runs;
  const double fit_seconds = ctx.seconds();
  ctx.note(fmt::format("calibrate: the intervals checked against the misfit along their axes ({} runs, {:.1f} s)",
                       check_runs, fit_seconds));
  for (const auto& w : iv.warnings) ctx.note("warning: " + w);

  const ForecastRuns runs = run_forecast(ctx, fit, iv);
  summary::Summary result = runs.calibrated;
  const Forecast f =
      forecast(result, runs.band, runs.steps, iv.covariance, iv.t, runs.design_time / project::seconds_per_day);
  result.detail[summary::keys::calibration] = calibration_json(ctx, fit, iv, f, fit_seconds);
  io::write_text_file(ctx.out / "calibration_fit.csv", fit_csv(p, fit.start_residuals, fit.residuals));
  io::write_text_file(ctx.out / "calibration.csv", parameters_csv(p, fit, iv));
  if (!runs.calibrated_text.empty()) io::write_text_file(ctx.out / "calibrated.json", runs.calibrated_text);
  io::write_summary(ctx.out, result);
  return summary::to_json(result);
}

}  // namespace frostwall::calibrate
