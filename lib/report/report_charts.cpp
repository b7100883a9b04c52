// The report's plots: wall thickness and OB temperature over time (wall.csv),
// temperature along OA and OB at the snapshot days (profiles_*.csv, the
// paper's Fig. 5), sensor readings (monitoring.csv); the front position of
// a plain geometry (summary.json).
#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>

#include "geometry/layout.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"
#include "report/svg_chart.hpp"

namespace frostwall::report::detail {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

json figure(const std::string& id, const std::string& title, const Chart& chart, const std::string& caption) {
  return {{"id", id}, {"title", title}, {"svg", render_svg(chart)}, {"caption", caption}};
}

std::optional<double> closure_day(const json& summary) {
  const auto& c = summary.value(keys::closure_time_days, json());
  return c.is_number() ? std::optional<double>(c.get<double>()) : std::nullopt;
}

std::optional<double> design_value(const json& summary, const char* key) {
  if (!summary.contains(keys::design) || !summary[keys::design].contains(key) ||
      !summary[keys::design][key].is_number())
    return std::nullopt;
  return summary[keys::design][key].get<double>();
}

// Ring radii of the layout, for marks on the profile plots.
std::vector<double> ring_radii(const RunRecord& run) {
  std::vector<double> radii;
  if (!run.project) return radii;
  const auto* s = std::get_if<project::ShaftSection>(&run.project->geometry);
  if (!s) return radii;
  for (const auto& p : geometry::pipe_positions(s->layout)) {
    const double r = std::hypot(p.x, p.y);
    if (std::none_of(radii.begin(), radii.end(), [&](double q) { return std::abs(q - r) < 1e-6; })) radii.push_back(r);
  }
  return radii;
}

// The estimated error of the thinnest ray and of OB at the snapshot days
// (numerics.error_estimate), as bars on the thickness chart.
// Returns the largest error drawn (0: none).
double add_thickness_error_bars(const json& summary, Chart& chart) {
  double largest = 0.0;
  const struct {
    const char* parent;
    const char* key;
    const char* colour;
  } bars[] = {{nullptr, "min_thickness", "#000000"}, {"OB", "thickness", "#E69F00"}};
  for (const auto& b : bars) {
    ErrorBars s;
    s.colour = b.colour;
    for (const auto& w : summary.value(keys::wall, json::array())) {
      const json& entry = b.parent ? w.value(b.parent, json::object()) : w;
      const json& e = entry.value(std::string(b.key) + "_error", json());
      if (!e.is_number() || !entry.value(b.key, json()).is_number()) continue;
      s.x.push_back(w[keys::day].get<double>());
      s.y.push_back(entry[b.key].get<double>());
      s.error.push_back(e.get<double>());
      largest = std::max(largest, e.get<double>());
    }
    if (!s.x.empty()) chart.error_bars.push_back(std::move(s));
  }
  return largest;
}

void wall_charts(const RunRecord& run, json& charts) {
  if (!fs::exists(run.dir / "wall.csv")) return;
  const CsvTable wall = read_csv(run.dir / "wall.csv");
  const auto* day = wall.column("day");
  if (!day || day->empty()) return;
  const auto closure = closure_day(run.summary);
  std::vector<Guide> closure_guide;
  if (closure) closure_guide.push_back({true, *closure, fmt::format("closure, day {}", number(*closure, 1))});

  Chart t;
  t.title = "frozen wall thickness over time";
  t.x_label = "time (d)";
  t.y_label = "wall thickness (m)";
  t.x_include = {0.0};
  t.y_include = {0.0};
  // The thinnest ray is often OB itself: drawn last, thin, on top of a wide OB.
  const struct {
    const char* column;
    const char* label;
    std::string colour;
    bool dashed;
    double width;
  } lines[] = {
      {"OA_thickness_m", "OA (through a pipe)", "#0072B2", true, 1.6},
      {"OB_thickness_m", "OB (between pipes)", "#E69F00", false, 3.2},
      {"min_thickness_m", "thinnest ray", "#000000", false, 1.2},
  };
  for (const auto& l : lines)
    if (const auto* c = wall.column(l.column))
      t.series.push_back({l.label, *day, *c, l.colour, l.dashed, false, l.width});
  const double largest_error = add_thickness_error_bars(run.summary, t);
  t.guides = closure_guide;
  if (const auto req = design_value(run.summary, keys::required_thickness))
    t.guides.push_back({false, *req, fmt::format("required {} m", number(*req, 2))});
  const std::string bars =
      largest_error > 0.0
          ? fmt::format(" The dots at the snapshot days carry the estimated numerical error of OB and of the "
                        "thinnest ray as bars (at most ± {} m here; smaller ones hide behind their dot).",
                        number(largest_error, 3))
          : std::string();
  charts.push_back(figure("thickness", "Wall thickness", t,
                          "Longest frozen stretch (liquid fraction at most 0.5) containing a ring of pipes, on OA, "
                          "on OB and on the thinnest ray of the wedge. Until the columns touch only the ground around "
                          "the pipes is frozen, so OB and the thinnest ray read zero; closure (the line) follows when "
                          "a fully frozen path has formed." +
                              bars));

  if (const auto* T = wall.column("mean_temperature_OB_C")) {
    Chart m;
    m.title = "mean temperature of the frozen wall on OB over time";
    m.x_label = "time (d)";
    m.y_label = "mean wall temperature on OB (°C)";
    m.x_include = {0.0, day->back()};  // the run's span even while OB has no frozen part
    m.y_include = {run.freezing_point()};
    m.empty_note = "OB not frozen within the run";
    m.series.push_back({"", *day, *T, "#0b3c73", false, false});
    m.guides = closure_guide;
    if (const auto limit = design_value(run.summary, keys::max_mean_temperature))
      m.guides.push_back({false, *limit, fmt::format("design limit {} °C", number(*limit, 1))});
    charts.push_back(figure("ob-temperature", "Mean wall temperature on OB", m,
                            "Mean temperature over the frozen part of OB (empty until OB freezes)."));
  }
}

void profile_chart(const RunRecord& run, const std::string& ray, json& charts) {
  const fs::path file = run.dir / ("profiles_" + ray + ".csv");
  if (!fs::exists(file)) return;
  const CsvTable t = read_csv(file);
  const auto* r = t.column("r_m");
  if (!r || t.header.size() < 2) return;
  Chart c;
  c.title = "temperature along " + ray + " at the snapshot days";
  c.x_label = "distance from the shaft axis (m)";
  c.y_label = "temperature (°C)";
  c.x_include = {0.0};
  const auto colours = sequential_colours(t.header.size() - 1);
  for (std::size_t k = 1; k < t.header.size(); ++k) {
    // Columns are named T_day_<day>_C.
    std::string label = t.header[k];
    if (label.rfind("T_day_", 0) == 0 && label.size() > 8) label = "day " + label.substr(6, label.size() - 8);
    c.series.push_back({label, *r, t.columns[k], colours[k - 1], false, false});
  }
  c.guides.push_back({false, run.freezing_point(), "freezing point"});
  for (double radius : ring_radii(run)) c.guides.push_back({true, radius, ""});
  if (run.project)
    if (const auto* s = std::get_if<project::ShaftSection>(&run.project->geometry); s && s->shaft.excavation_radius)
      c.guides.push_back({true, *s->shaft.excavation_radius, "excavation"});
  const std::string where = ray == "OA" ? "through a pipe of the outer ring" : "halfway between two outer pipes";
  charts.push_back(figure("profile-" + ray, "Temperature along " + ray, c,
                          "Temperature on the ray " + ray + " (" + where +
                              ") at each snapshot; dashed verticals: pipe rings and excavation."));
}

void sensor_chart(const RunRecord& run, json& charts) {
  const fs::path file = run.dir / "monitoring.csv";
  if (!fs::exists(file)) return;
  const CsvTable t = read_csv(file);
  // Shaft runs write days; plain geometries their own time unit.
  const std::string unit = run.shaft() ? "d" : run.summary.value(keys::run, json::object()).value("time_unit", "s");
  const auto* time = t.column(run.shaft() ? "day" : "time");
  if (!time || t.header.size() < 2) return;
  auto chart_of = [&](const std::string& suffix, const std::string& title, const std::string& y_label, double scale) {
    Chart c;
    c.title = title;
    c.x_label = "time (" + unit + ")";
    c.y_label = y_label;
    c.x_include = {0.0};
    for (std::size_t k = 1; k < t.header.size(); ++k) {
      const std::string& name = t.header[k];
      if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      std::vector<double> y = t.columns[k];
      for (double& v : y) v *= scale;
      c.series.push_back({name.substr(0, name.size() - suffix.size()), *time, y, "", false, false});
    }
    return c;
  };
  Chart c = chart_of("_C", "sensor temperatures over time", "temperature (°C)", 1.0);
  if (run.phase_change()) c.guides.push_back({false, run.freezing_point(), "freezing point"});
  charts.push_back(
      figure("sensors", "Sensors", c, "Temperature at the monitoring points (thermometer holes) of the project."));
  if (t.column(t.header.size() > 1 ? t.header[1].substr(0, t.header[1].size() - 2) + "_ux_m" : "")) {
    for (const auto& [suffix, axis] : {std::pair{std::string("_ux_m"), "x"}, std::pair{std::string("_uy_m"), "y"}})
      charts.push_back(
          figure("sensors-u" + std::string(axis), std::string("Sensors: displacement along ") + axis,
                 chart_of(suffix, std::string("displacement along ") + axis + " over time",
                          std::string("u") + axis + " (µm)", 1e6),
                 std::string("Displacement along ") + axis + " at the monitoring points (PD solid, linear MLS)."));
    charts.push_back(figure("sensors-damage", "Sensors: damage", chart_of("_damage", "damage over time", "damage", 1.0),
                            "Share of broken bonds at the monitoring points."));
  }
}

void front_chart(const RunRecord& run, json& charts) {
  const auto& front = run.summary.value(keys::front, json::array());
  if (!last_front(run.summary)) return;  // no front formed: nothing to chart
  Series s{"", {}, {}, "#0b3c73", false, front.size() < 40};
  for (const auto& p : front) {
    s.x.push_back(p[0].get<double>());
    s.y.push_back(p[1].is_number() ? p[1].get<double>() : std::numeric_limits<double>::quiet_NaN());
  }
  const std::string unit = run.summary.value(keys::run, json::object()).value("time_unit", "s");
  Chart c;
  c.title = "frozen front position over time";
  c.x_label = "time (" + unit + ")";
  c.y_label = "front position (m)";
  c.x_include = {0.0};
  c.y_include = {0.0};
  c.series.push_back(s);
  charts.push_back(figure("front", "Frozen front", c,
                          "Position of the frozen front from the cooled face along the problem's main axis."));
}

}  // namespace

void add_charts(const RunRecord& run, json& view) {
  json charts = json::array();
  if (run.shaft()) {
    wall_charts(run, charts);
    profile_chart(run, "OA", charts);
    profile_chart(run, "OB", charts);
    sensor_chart(run, charts);
  } else {
    front_chart(run, charts);
    sensor_chart(run, charts);
  }
  view["charts"] = charts;
}

}  // namespace frostwall::report::detail
