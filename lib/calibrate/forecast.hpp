// The forecast of a calibrated project: closure day and the thinnest wall
// at the design day, each with a band made of two parts added together:
// the spread the parameters' covariance C carries into it, t sqrt(g^T C g)
// with g its sensitivity to each parameter (one run per parameter, moved
// by its standard error), and the run's own numerical error bar (the
// error estimate of the calibrated run).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "calibrate/forward.hpp"
#include "project/project.hpp"
#include "summary/summary.hpp"

namespace frostwall::calibrate {

struct Band {
  std::optional<double> value, low, high;  // nullopt: not reached within the run
  double parameter_spread = 0.0;           // t sqrt(g^T C g)
  double run_error = 0.0;                  // the numerical error bar
};

struct Forecast {
  Band closure_day;
  Band thinnest_wall;  // m, at design_day
  double design_day = 0.0;
};

// The closure day and the wall's thinnest thickness at design_day from a
// run's summary (nullopt where the run did not get there).
std::optional<double> closure_day_of(const summary::Summary& s);
std::optional<double> wall_at(const summary::Summary& s, double day);

// `calibrated`: the summary of the calibrated run (with its error bars);
// `band`: the summaries of the band's runs, the first at the calibrated
// values, then one with parameter j moved by steps[j] for each j.
Forecast forecast(const summary::Summary& calibrated, const std::vector<summary::Summary>& band,
                  const std::vector<double>& steps, const Eigen::MatrixXd& covariance, double t, double design_day);

nlohmann::ordered_json forecast_json(const Forecast& f);

}  // namespace frostwall::calibrate
