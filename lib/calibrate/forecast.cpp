#include "calibrate/forecast.hpp"

#include <cmath>

#include "project/json_numbers.hpp"

namespace frostwall::calibrate {

namespace keys = summary::keys;

namespace {

// The error beside a number (`<key>_error` in the same object), 0 without one.
double error_at(const nlohmann::ordered_json& detail, const char* key) {
  const auto it = detail.find(keys::error_of(key));
  return it != detail.end() && it->is_number() ? it->get<double>() : 0.0;
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

std::optional<double> closure_day_of(const summary::Summary& s) { return s.closure_time_days; }

std::optional<double> wall_at(const summary::Summary& s, double day) {
  const auto* w = summary::wall_at(s, day);
  return w ? w->min_thickness : std::nullopt;
}

Forecast forecast(const summary::Summary& calibrated, const std::vector<summary::Summary>& band,
                  const std::vector<double>& steps, const Eigen::MatrixXd& covariance, double t, double design_day) {
  Forecast f;
  f.design_day = design_day;
  std::vector<std::optional<double>> closure, wall;
  for (const auto& s : band) {
    closure.push_back(closure_day_of(s));
    wall.push_back(calibrate::wall_at(s, design_day));
  }
  f.closure_day = band_of(closure_day_of(calibrated), error_at(calibrated.detail, keys::closure_time_days), closure,
                          steps, covariance, t);
  const auto* w = summary::wall_at(calibrated, design_day);
  f.thinnest_wall = band_of(calibrate::wall_at(calibrated, design_day),
                            w ? error_at(w->detail, keys::min_thickness) : 0.0, wall, steps, covariance, t);
  return f;
}

nlohmann::ordered_json forecast_json(const Forecast& f) {
  auto wall = band_json(f.thinnest_wall);
  wall["day"] = f.design_day;
  return {{"closure_day", band_json(f.closure_day)}, {"thinnest_wall", wall}};
}

}  // namespace frostwall::calibrate
