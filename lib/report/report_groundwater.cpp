// The groundwater section of a shaft run under seepage: the
// verdict, closure per gap with its side of the shaft, the wall's thinnest
// upstream and downstream, and the water through each gap over time (the
// last gap's stops when it closes). The flow field itself is drawn on the
// temperature maps (report/flow_arrows.hpp).
#include <fmt/core.h>

#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

void add_groundwater(const RunRecord& run, json& view) {
  view["has_groundwater"] = false;
  view["groundwater_gaps"] = json::array();
  view["groundwater_sides"] = json::array();
  view["groundwater_flow_svg"] = "";
  if (!run.summary.contains(keys::groundwater)) return;
  const json& g = run.summary[keys::groundwater];
  view["has_groundwater"] = true;
  const auto& q = g.value("darcy_flux_m_per_day", json::array({0.0, 0.0}));
  view["groundwater_note"] =
      fmt::format("Regional Darcy flux ({}, {}) m/d; permeability {:.3g} m²; law {}; the flow was solved {} times. {}.",
                  number(q[0], 2), number(q[1], 2), g.value("permeability_m2", 0.0), g.value("permeability_law", ""),
                  g.value("flow_solves", 0), g.value(keys::verdict, ""));
  std::vector<Series> series;
  for (const auto& gap : g.value(keys::gaps, json::array())) {
    view["groundwater_gaps"].push_back(
        {{"between", gap.value("between", "")},
         {"position", gap.value("position", "")},
         {"closure_day", with_error(gap[keys::closure_day], gap.value(keys::error_of(keys::closure_day), json()), 2)}});
    if (!gap.contains("flow")) continue;
    Series s;
    s.label = gap.value("between", "") + " (" + gap.value("position", "") + ")";
    s.x = gap["flow"].value("days", std::vector<double>{});
    s.y = gap["flow"].value("m3_per_day_per_m", std::vector<double>{});
    series.push_back(std::move(s));
  }
  for (const auto& w : run.summary.value(keys::wall, json::array()))
    if (w.contains(keys::min_thickness_upstream))
      view["groundwater_sides"].push_back({{"day", number(w[keys::day], 1)},
                                           {"upstream", number(w[keys::min_thickness_upstream], 2)},
                                           {"downstream", number(w[keys::min_thickness_downstream], 2)},
                                           {"thinnest", number(w[keys::min_thickness], 2)}});
  Chart chart = line_chart("Water through each gap", "time (d)", "flow (m³/d per m of depth)", std::move(series));
  chart.y_include = {0.0};
  view["groundwater_flow_svg"] = render_svg(chart);
}

}  // namespace frostwall::report::detail
