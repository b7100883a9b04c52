// Calibration from thermometers: each sensor's readings against the curves
// of the start and fitted parameters, the parameter table with its 95 %
// intervals and correlations, the warnings on identifiability, and the
// forecast with its band (summary.json "calibration", calibration_fit.csv).
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <map>
#include <sstream>

#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

struct SensorCurves {
  std::vector<double> time, measured, start, fitted;
};

// calibration_fit.csv: sensor,time,measured_C,start_C,fitted_C, by sensor.
std::map<std::string, SensorCurves> read_fit(const std::filesystem::path& file) {
  std::map<std::string, SensorCurves> by_sensor;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string sensor, cell;
    std::getline(cells, sensor, ',');
    double v[4];
    for (double& x : v) {
      std::getline(cells, cell, ',');
      x = std::stod(cell);
    }
    auto& s = by_sensor[sensor];
    s.time.push_back(v[0]), s.measured.push_back(v[1]), s.start.push_back(v[2]), s.fitted.push_back(v[3]);
  }
  return by_sensor;
}

std::string sensor_chart(const std::string& name, const SensorCurves& c, const std::string& unit) {
  Chart chart;
  chart.title = "sensor " + name + ": measured and simulated";
  chart.x_label = "time (" + unit + ")";
  chart.y_label = "temperature (°C)";
  chart.width = 420, chart.height = 260;
  chart.series.push_back({"measured", c.time, c.measured, "#000000", false, true, 0.0});
  chart.series.push_back({"project's values", c.time, c.start, "#999999", true, false});
  chart.series.push_back({"fitted", c.time, c.fitted, "#D55E00", false, false});
  chart.guides.push_back({false, 0.0, ""});
  return render_svg(chart);
}

std::string band_text(const json& band, int decimals, const std::string& unit) {
  if (!band.value("value", json()).is_number()) return "not reached within the run";
  std::string text = number(band["value"], decimals) + " " + unit;
  if (band.value("low", json()).is_number())
    text += " (" + number(band["low"], decimals) + " to " + number(band["high"], decimals) + ")";
  return text;
}

}  // namespace

void add_calibration(const RunRecord& run, json& view) {
  view["has_calibration"] = false;
  view["has_calibration_warnings"] = false;
  for (const char* key : {"calibration_note", "calibration_forecast_note"}) view[key] = "";
  for (const char* key : {"calibration_charts", "calibration_rows", "calibration_names", "calibration_correlation",
                          "calibration_warnings", "calibration_forecast"})
    view[key] = json::array();
  const json& s = run.summary;
  if (!s.contains(keys::calibration)) return;
  const json& c = s[keys::calibration];
  view["has_calibration"] = true;
  const std::string unit = s.value(keys::run, json::object()).value("time_unit", "d");
  json charts = json::array();
  for (const auto& [name, curves] : read_fit(run.dir / "calibration_fit.csv"))
    charts.push_back({{"svg", sensor_chart(name, curves, unit)}, {"caption", "Sensor " + name + "."}});
  view["calibration_charts"] = charts;
  json rows = json::array();
  for (const auto& [name, q] : c[keys::parameters].items()) {
    const int decimals = q["unit"] == "degC" ? 2 : 3;
    rows.push_back({{"name", name},
                    {"unit", q["unit"]},
                    {"start", number(q["start"], decimals)},
                    {"value", number(q["value"], decimals)},
                    {"interval", number(q["low"], decimals) + " – " + number(q["high"], decimals)},
                    {"bounds", number(q["bounds"][0], decimals) + " – " + number(q["bounds"][1], decimals)},
                    {"identified", q["identified"].get<bool>() ? "yes" : "no"}});
  }
  view["calibration_rows"] = rows;
  json correlation = json::array();
  const auto& names = c["correlation"][keys::parameters];
  for (std::size_t i = 0; i < names.size(); ++i) {
    json cells = json::array();
    for (std::size_t j = 0; j < names.size(); ++j) {
      const double r = c["correlation"]["matrix"][i][j];
      cells.push_back({{"value", number(r, 2)}, {"strong", i != j && std::abs(r) > 0.95}});
    }
    correlation.push_back({{"name", names[i]}, {"cells", cells}});
  }
  view["calibration_names"] = names;
  view["calibration_correlation"] = correlation;
  json warnings = json::array();
  for (const auto& w : c[keys::warnings]) warnings.push_back({{"text", w}});
  view["calibration_warnings"] = warnings;
  view["has_calibration_warnings"] = !warnings.empty();
  view["calibration_note"] = fmt::format(
      "{} readings of {} sensors ({}) to {}, fitted by weighted least squares: rms misfit {} K with the "
      "project's values, {} K fitted ({} iterations, {} runs, {} s). Intervals are 95 % (Student's t {}), from "
      "the Jacobian at the optimum with a noise of {} K ({}).",
      c["reading_count"].get<int>(), c["sensors"].size(), c.value("readings", ""),
      unit == "d"
          ? "day " + number(c["last_reading_day"], 1)
          : number(c["last_reading_day"].get<double>() * project::seconds_per_day / (unit == "h" ? 3600.0 : 1.0), 1) +
                " " + unit,
      number(c["rms_misfit_before"], 3), number(c["rms_misfit_after"], 3), c["iterations"].get<int>(),
      c["forward_runs"].get<int>(), number(c["fit_seconds"], 0), number(c["t_quantile"], 2), number(c["noise"], 3),
      c["noise_given"].get<bool>() ? "as given" : "estimated from the misfit");
  const json& f = c[keys::forecast];
  view["calibration_forecast"] =
      json::array({{{"what", "closure"}, {"value", band_text(f[keys::closure_day], 1, "d")}},
                   {{"what", "thinnest wall on day " + number(f[keys::thinnest_wall][keys::day], 0)},
                    {"value", band_text(f[keys::thinnest_wall], 2, "m")}}});
  view["calibration_forecast_note"] = fmt::format(
      "The band adds the spread the parameters' intervals carry into each number ({} d for closure) to the run's "
      "own numerical error bar ({} d).",
      number(f[keys::closure_day]["parameter_spread"], 2), number(f[keys::closure_day]["run_error"], 2));
}

}  // namespace frostwall::report::detail
