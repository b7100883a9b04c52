// The parts of the report view, one builder per section (internal to
// lib/report). Each adds its keys to the view.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>

#include "particles/vec.hpp"
#include "project/project.hpp"
#include "report/colour_scale.hpp"
#include "report/svg_chart.hpp"
#include "report/view_numbers.hpp"
#include "report/wedge_symmetry.hpp"
#include "summary/summary.hpp"

namespace frostwall::report {
namespace keys = summary::keys;
}  // namespace frostwall::report

namespace frostwall::report::detail {

// The mirror wedge a run simulated (summary "wedge"); the full circle when
// it has none.
WedgeSymmetry wedge_of(const nlohmann::json& summary);

// Everything read from a run's output directory.
struct RunRecord {
  std::filesystem::path dir;
  nlohmann::json summary;
  std::optional<project::Project> project;  // from project.json, when recorded and valid
  bool shaft() const { return summary.contains(keys::wall); }
  // A PD solid ran (summary run.mechanics); a porous plate froze (summary pores).
  bool mechanics() const { return summary.value(keys::run, nlohmann::json::object()).contains("mechanics"); }
  bool frost() const { return summary.contains(keys::pores) && summary[keys::pores].is_array(); }
  // The freezing point of what freezes: the pore water of a porous plate, else the soil.
  double freezing_point() const {
    return project ? (frost() ? project->pore_fluid.freezing_point : project->soil.freezing_point) : 0.0;
  }
  // Whether anything can freeze (a soil with latent heat, or pore water).
  bool phase_change() const { return !project || frost() || project->soil.latent_heat > 0.0; }
};

// The run's smoothing length (summary.json run.smoothing_length, m): the
// maps sample the particles' fields with the run's own kernel width.
// Throws std::runtime_error when the summary lacks it.
double smoothing_length(const nlohmann::json& run_facts);

// A length in m: `decimals` places from a millimetre up, four significant
// digits below (a plate of micrometres).
std::string metres(double v, int decimals);
// A number with its estimated error, "13.88 ± 0.16": the error to one
// significant digit (two when it starts with 1), the value to the same
// place. Without an error (null, missing): number(value, decimals).
std::string with_error(const nlohmann::json& value, const nlohmann::json& error, int decimals);

// The method that ran, for the title block ("Peridynamics: ...").
std::string method_line(const RunRecord& run);
// Headline cards of a plain geometry: the front and sensors of a thermal
// run; displacement, broken bonds and cracks of a PD solid; the pores'
// freezing and cracking of a porous plate.
void add_plain_headline(const RunRecord& run, nlohmann::json& view);
// Temperature maps of a plain geometry's snapshots on the particles'
// triangles (a plain thermal run's maps section).
void add_plain_maps(const RunRecord& run, nlohmann::json& view);
// One colour scale over every snapshot's temperature, ends at round
// values, turning from blue to red at the freezing point.
ColourScale temperature_scale(const std::vector<std::vector<double>>& snapshots, double freezing_point);
// The longest edge of a triangle of the particles' cloud for the maps
// (longer ones cross a hole): from summary.json's spacing facts.
double triangle_edge(const nlohmann::json& run_facts);
// The last snapshot of a plain geometry's front ("front": [[t, x], ...])
// at which a front had formed (beyond the face's own row of particles);
// nullopt for a run that never froze.
std::optional<std::pair<double, double>> last_front(const nlohmann::json& summary);
// A card of the headline.
nlohmann::json card(const std::string& label, const std::string& value, const std::string& note);
// A row of a two-column table: {"label": ..., "value": ...}.
nlohmann::json row(const std::string& label, const std::string& value);
// A chart's line (colour empty: the next categorical colour).
Series line(std::string label, std::vector<double> x, std::vector<double> y, std::string colour = "",
            bool dashed = false);

void add_project(const RunRecord& run, nlohmann::json& view);    // layout, soil, schedule, numerics, design
void add_headline(const RunRecord& run, nlohmann::json& view);   // closure, thickness, design check, table
void add_maps(const RunRecord& run, nlohmann::json& view);       // temperature maps and colour bar
void add_charts(const RunRecord& run, nlohmann::json& view);     // thickness, OB temperature, profiles, sensors
void add_mechanics(const RunRecord& run, nlohmann::json& view);  // PD: displacement and damage maps
void add_frost(const RunRecord& run, nlohmann::json& view);      // porous plate: maps, pore freezing, damage
void add_run_facts(const RunRecord& run, nlohmann::json& view);  // run table and file links
void add_groundwater(const RunRecord& run, nlohmann::json& view);
void add_plant(const RunRecord& run,
               nlohmann::json& view);  // plant: sizing, load, supply and return, brine along the pipe
// Sinking the shaft: the critical section in the first lines, the sections' table and charts.
void add_excavation(const RunRecord& run, nlohmann::json& view);
void add_as_built(
    const RunRecord& run,
    nlohmann::json& view);  // sections at depth: charts, plan, table  // seepage: verdict, gaps, sides, gap flow
// Calibration from thermometers: sensors' curves, parameters, forecast band.
void add_calibration(const RunRecord& run, nlohmann::json& view);
void add_cfd_dem(const RunRecord& run, nlohmann::json& view);  // CFD-DEM: bed, fluidisation, curves, run, files
void add_erosion(const RunRecord& run, nlohmann::json& view);
void add_design(const RunRecord& run,
                nlohmann::json& view);  // wall check: verdict, formulas, required vs achieved, layers, brine
// "design met on day 47 in clay at 200 m; utilisation 0.93 on day 120"
std::string design_verdict(const nlohmann::json& summary);
// A line chart with its titles (the CFD-DEM sections' charts).
Chart line_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                 std::vector<Series> series);  // CFD-DEM over a cavity: losses, settlement, section maps

}  // namespace frostwall::report::detail
