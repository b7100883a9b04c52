// Sinking the shaft: the critical section, day and margin named in the
// report's first lines and on a headline card; a table of every section's
// excavation (its day, the lining's, the thinnest wall after and the
// smallest margin), and each section's wall thickness and margin against
// the days after its excavation.
#include <fmt/core.h>

#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

// The shaft's sections with their series: a layered or as-built shaft's
// overview holds them; one section's series is its own entry's.
json sections_of(const json& e) {
  if (!e.contains("series")) return e["sections"];
  json s = e;
  s["name"] = e["sections"][0]["name"];
  return json::array({s});
}

std::string metres_or_dash(const json& v) { return v.is_number() ? number(v, 2) + " m" : std::string("–"); }

}  // namespace

void add_excavation(const RunRecord& run, json& view) {
  view["has_excavation"] = false;
  view["excavation_card"] = false;
  view["excavation_line"] = false;
  if (!run.summary.contains(keys::excavation)) return;
  const json& e = run.summary[keys::excavation];
  const json sections = sections_of(e);
  view["has_excavation"] = true;
  const json &depth = e["critical_depth"], &day = e["critical_day"], &least = e["margin_min"];
  if (depth.is_number() && day.is_number()) {
    const std::string margin = least.is_number() ? fmt::format("smallest margin {} m", number(least, 2))
                                                 : std::string("no requirement to measure a margin against");
    view["excavation_line"] =
        fmt::format("Sinking: the wall is weakest at {} m depth{} on day {}: {}.", number(depth, 1),
                    sections.size() == 1 ? std::string() : " (" + e.value("critical_section", std::string()) + ")",
                    number(day, 1), margin);
    view["excavation_card"] = true;
    view["excavation_value"] = least.is_number() ? number(least, 2) + " m" : "–";
    view["excavation_note"] =
        fmt::format("smallest margin after excavation: {} m depth, day {}", number(depth, 1), number(day, 1));
  }
  json rows = json::array();
  std::vector<Series> thickness, margin;
  for (const auto& s : sections) {
    const std::string name = s.value("name", std::string());
    rows.push_back({{"name", name},
                    {"depth", number(s["depth"], 1)},
                    {"day", number(s["day"], 1)},
                    {"lining", s.contains("lining_day") ? number(s["lining_day"], 1) : std::string("–")},
                    {"thinnest", metres_or_dash(s["thinnest_after"])},
                    {"margin", metres_or_dash(s["margin_min"])},
                    {"margin_day", s["margin_min_day"].is_number() ? number(s["margin_min_day"], 1) : "–"}});
    std::vector<double> after, t, m;
    for (const auto& r : s.value("series", json::array())) {
      after.push_back(r["days_after"].get<double>());
      t.push_back(r["thickness"].get<double>());
      m.push_back(r["margin"].is_number() ? r["margin"].get<double>() : std::nan(""));
    }
    thickness.push_back(line(name, after, t));
    margin.push_back(line(name, after, m));
  }
  view["excavation_sections"] = rows;
  const std::string on = sections[0].value("measured_on", std::string("frozen front"));
  Chart wall = line_chart("The wall after excavation", "days after excavation (d)", "thinnest wall (m)", thickness);
  wall.y_include = {0.0};
  Chart spare = line_chart("The margin after excavation", "days after excavation (d)", "margin (m)", margin);
  spare.guides.push_back({false, 0.0, "no margin"});
  view["excavation_charts"] = json::array(
      {{{"svg", render_svg(wall)},
        {"caption", fmt::format("The thinnest wall from the face outward ({}), each section from its day.", on)}},
       {{"svg", render_svg(spare)},
        {"caption", "The wall's thickness less the thickness the ground pressure needs at the wall's mean "
                    "temperature (below 0 the wall does not carry it)."}}});
}

}  // namespace frostwall::report::detail
