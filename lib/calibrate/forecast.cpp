#include "calibrate/forecast.hpp"

#include <cmath>

#include "project/json_numbers.hpp"

namespace frostwall::calibrate {

using project::number_at;

namespace {

const nlohmann::json* wall_entry(const nlohmann::json& summary, double day) {
  if (!summary.contains("wall") || !summary["wall"].is_array()) return nullptr;
  for (const auto& w : summary["wall"])
    if (w.contains("day") && std::abs(w["day"].get<double>() - day) <= 1e-9 * std::max(1.0, day)) return &w;
  return nullptr;
}

// One number's band: its value, and its value in each of the band's runs.
Band band_of(std::optional<double> value, double run_error, const std::vector<std::optional<double>>& band,
             const std::vector<double>& steps, const Eigen::MatrixXd& covariance, double t) {
  Band b;
  b.value = value;
  b.run_error = run_error;
  if (!value) return b;
  Eigen::VectorXd g(static_cast<Eigen::Index>(steps.size()));
  for (std::size_t j = 0; j < steps.size(); ++j) {
    if (!band[0] || !band[j + 1]) return b;  // a run that did not get there: no band to speak of
    g(static_cast<Eigen::Index>(j)) = (*band[j + 1] - *band[0]) / steps[j];
  }
  b.parameter_spread = t * std::sqrt(std::max(0.0, g.dot(covariance * g)));
  b.low = *value - b.parameter_spread - run_error;
  b.high = *value + b.parameter_spread + run_error;
  return b;
}

nlohmann::ordered_json band_json(const Band& b) {
  auto number = [](const std::optional<double>& v) { return v ? nlohmann::ordered_json(*v) : nullptr; };
  return {{"value", number(b.value)},
          {"low", number(b.low)},
          {"high", number(b.high)},
          {"parameter_spread", b.parameter_spread},
          {"run_error", b.run_error}};
}

}  // namespace

std::optional<double> closure_day_of(const nlohmann::json& summary) { return number_at(summary, "closure_time_days"); }

std::optional<double> wall_at(const nlohmann::json& summary, double day) {
  const auto* w = wall_entry(summary, day);
  return w ? number_at(*w, "min_thickness") : std::nullopt;
}

Forecast forecast(const nlohmann::json& calibrated, const std::vector<nlohmann::json>& band,
                  const std::vector<double>& steps, const Eigen::MatrixXd& covariance, double t, double design_day) {
  Forecast f;
  f.design_day = design_day;
  std::vector<std::optional<double>> closure, wall;
  for (const auto& s : band) {
    closure.push_back(closure_day_of(s));
    wall.push_back(wall_at(s, design_day));
  }
  f.closure_day = band_of(closure_day_of(calibrated), number_at(calibrated, "closure_time_days_error").value_or(0.0),
                          closure, steps, covariance, t);
  const auto* w = wall_entry(calibrated, design_day);
  f.thinnest_wall = band_of(wall_at(calibrated, design_day),
                            w ? number_at(*w, "min_thickness_error").value_or(0.0) : 0.0, wall, steps, covariance, t);
  return f;
}

nlohmann::ordered_json forecast_json(const Forecast& f) {
  auto wall = band_json(f.thinnest_wall);
  wall["day"] = f.design_day;
  return {{"closure_day", band_json(f.closure_day)}, {"thinnest_wall", wall}};
}

}  // namespace frostwall::calibrate
