// The shaft as built: the sections at depth against each other (largest
// gap, closure day, thinnest wall, design margin, each against depth with
// the critical depth marked), the plan at the critical depth over the
// design positions, and a table by depth.
#include <cmath>
#include <fmt/core.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <limits>
#include <numbers>

#include "report/layout_drawing.hpp"
#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

double value_or_nan(const json& v) {
  return v.is_number() ? v.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

std::vector<geometry::Pipe2> pipes_of(const json& list) {
  std::vector<geometry::Pipe2> pipes;
  for (const auto& q : list) {
    geometry::Pipe2 p;
    p.number = q[0], p.x = q[1], p.y = q[2], p.failed = q[3];
    p.label = fmt::format("pipe {}", p.number);
    pipes.push_back(p);
  }
  return pipes;
}

// One quantity of every section against depth.
std::string depth_chart(const json& sections, const char* key, const std::string& what, const std::string& unit,
                        double critical, const char* intact_key = nullptr) {
  Chart c;
  c.title = what + " against depth";
  c.x_label = "depth (m)";
  c.y_label = what + " (" + unit + ")";
  c.width = 420, c.height = 260;
  Series s{"as built", {}, {}, "#0072B2", false, true};
  Series intact{"intact", {}, {}, "#999999", true, true};
  for (const auto& e : sections) {
    s.x.push_back(e["depth"]);
    s.y.push_back(value_or_nan(e.value(key, json())));
    if (intact_key && e.contains(keys::intact)) {
      intact.x.push_back(e["depth"]);
      intact.y.push_back(value_or_nan(e[keys::intact].value(intact_key, json())));
    }
  }
  c.series.push_back(s);
  if (!intact.x.empty()) c.series.push_back(intact);
  c.guides.push_back({true, critical, "critical"});
  c.empty_note = "not reached at any depth";
  return render_svg(c);
}

}  // namespace

// A failed-pipe scenario beside the intact layout: the two side by side.
void add_intact_pair(const RunRecord& run, json& view) {
  const json& s = run.summary;
  view["has_intact_pair"] = false;
  if (s.contains(keys::sections) || !s.value(keys::intact, json()).is_object()) return;
  view["has_intact_pair"] = true;
  const json wall = s.value(keys::wall, json::array());
  const json last = wall.empty() ? json::object() : wall.back();
  const json& intact = s[keys::intact];
  const auto failed = run.project ? std::get<project::ShaftSection>(run.project->geometry).layout.failed_pipes
                                  : std::vector<int>{};
  view["intact_rows"] = json::array({{{"what", fmt::format("pipes {} failed", fmt::join(failed, ", "))},
                                      {"closure", number(s[keys::closure_time_days], 1)},
                                      {"thinnest", number(last.value(keys::min_thickness, json()), 2)},
                                      {"angle", number(last.value(keys::thinnest_angle_deg, json()), 1)},
                                      {"margin", number(s.value(keys::design_margin, json()), 2)},
                                      {"report", "failed/report.html"}},
                                     {{"what", "every pipe working"},
                                      {"closure", number(intact[keys::closure_time_days], 1)},
                                      {"thinnest", number(intact[keys::thinnest_wall], 2)},
                                      {"angle", number(intact[keys::thinnest_angle_deg], 1)},
                                      {"margin", number(intact[keys::design_margin], 2)},
                                      {"report", "intact/report.html"}}});
}

void add_as_built(const RunRecord& run, json& view) {
  view["has_as_built"] = false;
  add_intact_pair(run, view);
  const json& s = run.summary;
  if (!s.contains(keys::sections) || !run.project) return;
  const json& sections = s[keys::sections];
  const double critical = s.value(keys::critical_depth, 0.0);
  view["has_as_built"] = true;
  const json info = s.value(keys::as_built, json::object());
  view["as_built_note"] = fmt::format(
      "{} sections of the full ring, each with the pipes where the survey ({}, {}) puts them at that depth{}. The "
      "critical depth, {} m, is {}.",
      sections.size(), info.value("survey", ""), info.value("form", ""),
      info.value("failed_pipes", json::array()).empty() ? std::string()
                                                        : fmt::format(" and pipes {} off", info["failed_pipes"].dump()),
      number(critical, 1),
      std::all_of(sections.begin(), sections.end(),
                  [](const json& e) { return e.value(keys::design_margin, json()).is_number(); })
          ? "the one with the smallest design margin"
          : "the one that closes last");
  json charts = json::array();
  charts.push_back({{"svg", depth_chart(sections, "largest_gap", "largest gap", "m", critical)},
                    {"caption", "The widest opening between neighbouring working pipes of a ring, wall to wall."}});
  charts.push_back(
      {{"svg", depth_chart(sections, keys::closure_time_days, "closure", "d", critical, keys::closure_time_days)},
       {"caption", "The day the wall closes; no point where it does not close within the run."}});
  charts.push_back(
      {{"svg", depth_chart(sections, keys::thinnest_wall, "thinnest wall", "m", critical, keys::thinnest_wall)},
       {"caption", "The thinnest frozen wall on any ray of the full ring, at the last snapshot."}});
  charts.push_back(
      {{"svg", depth_chart(sections, keys::design_margin, "design margin", "share", critical, keys::design_margin)},
       {"caption", "The smallest of 1 − utilisation, the thinnest wall over the required thickness minus 1, and the "
                   "mean temperature's distance below its limit over the limit, at the last snapshot; below 0 the "
                   "design is not met."}});
  view["as_built_charts"] = charts;

  // The plan at the critical depth over the design positions.
  const auto& section = std::get<project::ShaftSection>(run.project->geometry);
  json rows = json::array();
  for (const auto& e : sections) {
    std::string between;
    for (const auto& g : e.value("largest_gaps", json::array()))
      between += (between.empty() ? "" : ", ") +
                 fmt::format("{}–{}", g["between"][0].get<int>(), g["between"][1].get<int>());
    const json intact = e.value(keys::intact, json());
    rows.push_back({{"depth", number(e["depth"], 1)},
                    {"critical", e.value("critical", false) ? "critical" : ""},
                    {"layer", e.value("layer", json()).is_string() ? e["layer"].get<std::string>() : "–"},
                    {"gap", number(e["largest_gap"], 3)},
                    {"between", between},
                    {"closure", number(e[keys::closure_time_days], 1)},
                    {"thinnest", number(e[keys::thinnest_wall], 2)},
                    {"angle", number(e[keys::thinnest_angle_deg], 1)},
                    {"margin", number(e[keys::design_margin], 2)},
                    {"intact_closure", intact.is_object() ? number(intact[keys::closure_time_days], 1) : "–"},
                    {"intact_thinnest", intact.is_object() ? number(intact[keys::thinnest_wall], 2) : "–"},
                    {"report", e.value("directory", "") + "/report.html"}});
    if (!e.value("critical", false)) continue;
    LayoutDrawing drawing;
    drawing.section = &section;
    drawing.pipes = pipes_of(e.value("pipes", json::array()));
    drawing.design_pipes = pipes_of(info.value("design_pipes", json::array()));
    if (e[keys::thinnest_angle_deg].is_number())
      drawing.thinnest_ray = e[keys::thinnest_angle_deg].get<double>() * std::numbers::pi / 180;
    view["as_built_plan_svg"] = layout_svg(drawing, 520);
  }
  view["as_built_rows"] = rows;
  view["as_built_has_intact"] =
      std::any_of(sections.begin(), sections.end(), [](const json& e) { return e.contains(keys::intact); });
}

}  // namespace frostwall::report::detail
