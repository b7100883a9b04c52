#include "study/study_seepage.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

#include "report/svg_chart.hpp"
#include "report/view_numbers.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace keys = summary::keys;

using nlohmann::json;

namespace {

using report::get;
using report::number;

// |q| in m/d; 0 for still water.
double seepage(const json& summary) {
  if (!summary.contains(keys::groundwater)) return 0.0;
  const auto& q = summary[keys::groundwater]["darcy_flux_m_per_day"];
  return std::hypot(q[0].get<double>(), q[1].get<double>());
}

// The critical flux, bracketed by the variants: the wall stops closing
// between the fastest flux at which it closed and the slowest at which it
// did not (within each run's time).
std::string critical_flux(const std::vector<double>& closed, const std::vector<double>& open, double end) {
  if (closed.empty() && open.empty()) return "";
  auto flux = [](double q) { return fmt::format("{:.3g}", q); };
  const double fastest_closed = closed.empty() ? NAN : *std::max_element(closed.begin(), closed.end());
  const double slowest_open = open.empty() ? NAN : *std::min_element(open.begin(), open.end());
  if (open.empty())
    return fmt::format("The wall closed at every flux up to {} m/d: the critical flux is above it.",
                       flux(fastest_closed));
  if (closed.empty())
    return fmt::format("The wall did not close at any flux from {} m/d within {} days: the critical flux is below it.",
                       flux(slowest_open), number(end, 0));
  if (fastest_closed < slowest_open)
    return fmt::format(
        "Critical flux: the wall stops closing between {} m/d (the fastest that closed) and {} m/d (the slowest that "
        "did not close within {} days).",
        flux(fastest_closed), flux(slowest_open), number(end, 0));
  return fmt::format("The wall closed at {} m/d but not at {} m/d: the variants do not bracket one critical flux.",
                     flux(fastest_closed), flux(slowest_open));
}

}  // namespace

bool has_seepage(const StudyRun& run) {
  for (const auto& v : run.variants)
    if (v.ok && v.summary.contains(keys::groundwater)) return true;
  return false;
}

void add_seepage(const StudyRun& run, json& view) {
  view["has_seepage"] = has_seepage(run);
  if (!view["has_seepage"].get<bool>()) return;
  json rows = json::array();
  report::Series closed{"closed", {}, {}, "", false, true, 1.8};
  report::Series open{"no closure (at the run's end)", {}, {}, "#c0392b", true, true, 1.2};
  double end = 0.0;
  for (const auto& v : run.variants) {
    if (!v.ok || !v.summary.contains(keys::wall)) continue;
    const double q = seepage(v.summary), closure = get(v.summary, keys::closure_time_days);
    const json& walls = v.summary[keys::wall];
    const json last_wall = walls.empty() ? json::object() : walls.back();
    end = std::max(end, get(last_wall, keys::day));
    if (std::isfinite(closure)) closed.x.push_back(q), closed.y.push_back(closure);
    else open.x.push_back(q), open.y.push_back(get(last_wall, keys::day));
    const json g = v.summary.value(keys::groundwater, json::object());
    const json gap = g.value("last_gap", json(nullptr));
    rows.push_back(
        {{"name", v.name},
         {"href", v.name + "/report.html"},
         {"flux", number(q, 2)},
         {"closure", number(closure, 2)},
         {"last_gap",
          gap.is_object() ? fmt::format("{} ({})", gap.value("between", ""), gap.value("position", "")) : "–"},
         {"upstream", number(get(last_wall, keys::min_thickness_upstream), 2)},
         {"downstream", number(get(last_wall, keys::min_thickness_downstream), 2)},
         {"day", number(get(last_wall, keys::day), 1)},
         {"verdict", g.value(keys::verdict, std::string("still water"))}});
  }
  report::Chart chart;
  chart.title = "closure against the regional seepage";
  chart.x_label = "regional Darcy flux (m/d)";
  chart.y_label = "closure (day)";
  chart.x_include = {0.0};
  chart.y_include = {0.0};
  view["seepage_critical"] = critical_flux(closed.x, open.x, end);
  chart.series.push_back(std::move(closed));
  if (!open.x.empty()) chart.series.push_back(std::move(open));
  view["seepage_rows"] = rows;
  view["seepage_chart_svg"] = report::render_svg(chart);
}

}  // namespace frostwall::study
