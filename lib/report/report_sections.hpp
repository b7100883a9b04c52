// The parts of the report view, one builder per section (internal to
// lib/report). Each adds its keys to the view.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "project/project.hpp"
#include "report/svg_chart.hpp"

namespace frostwall::report::detail {

// Everything read from a run's output directory.
struct RunRecord {
  std::filesystem::path dir;
  nlohmann::json summary;
  std::optional<project::Project> project;  // from project.json, when recorded and valid
  bool shaft() const { return summary.contains("wall"); }
  double freezing_point() const { return project ? project->soil.freezing_point : 0.0; }
};

// "1.23" with a true minus sign; "–" for null/NaN.
// The run's smoothing length (summary.json run.smoothing_length, m): the
// maps sample the particles' fields with the run's own kernel width.
// Throws std::runtime_error when the summary lacks it.
double smoothing_length(const nlohmann::json& run_facts);

std::string number(double v, int decimals);
std::string number(const nlohmann::json& v, int decimals);

void add_project(const RunRecord& run, nlohmann::json& view);   // layout, soil, schedule, numerics, design
void add_headline(const RunRecord& run, nlohmann::json& view);  // closure, thickness, design check, table
void add_maps(const RunRecord& run, nlohmann::json& view);      // temperature maps and colour bar
void add_charts(const RunRecord& run, nlohmann::json& view);    // thickness, OB temperature, profiles, sensors
void add_mechanics(const RunRecord& run, nlohmann::json& view); // PD: displacement and damage maps
void add_frost(const RunRecord& run, nlohmann::json& view);     // porous plate: maps, pore freezing, damage
void add_run_facts(const RunRecord& run, nlohmann::json& view); // run table and file links
void add_groundwater(const RunRecord& run, nlohmann::json& view); // seepage: verdict, gaps, sides, gap flow
void add_cfd_dem(const RunRecord& run, nlohmann::json& view);   // CFD-DEM: bed, fluidisation, curves, run, files
void add_erosion(const RunRecord& run, nlohmann::json& view);
void add_design(const RunRecord& run, nlohmann::json& view);    // wall check: verdict, formulas, required vs achieved, layers, brine
// "design met on day 47 in clay at 200 m; utilisation 0.93 on day 120"
std::string design_verdict(const nlohmann::json& summary);
// A line chart with its titles (the CFD-DEM sections' charts).
Chart line_chart(const std::string& title, const std::string& x_label, const std::string& y_label, std::vector<Series> series);   // CFD-DEM over a cavity: losses, settlement, section maps

}  // namespace frostwall::report::detail
