// summary.json, the interface between the engines and everything built on
// their results (the report, studies, the error estimate, calibration):
// its keys, and the shared headline as a typed structure.
//
// The keys are the summary.json contract that docs/reference/README.md
// documents: fields are added, never renamed or dropped. Every key the
// code reads or writes is a constant of `keys`; each is documented in
// docs/reference/ (tests/test_summary.cpp checks it).
//
// `Summary` types the headline every consumer shares: the project's name
// and version, closure and contact days, the wall per snapshot, the design
// check, the run's facts and the warnings. Everything else (the engines'
// own blocks: groundwater, monitoring, brine, pores and damage, the
// CFD-DEM soil, sections, calibration, error entries) stays as JSON in
// `detail`, read and written by key constant: typing every engine's block
// would be a rewrite of each engine's results for no reader's gain.
//
// Key order is part of the file: `detail` holds every key of the object in
// its place, the typed members' keys as slots there (null; an empty array
// for the lists wall and warnings), so
// to_json(from_json(j)) is j, order included. A typed member that is set
// without a slot (a new summary) is appended after the keys in place.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace frostwall::summary {

// X(name): the key spelled as the constant's name.
// clang-format off
#define FROSTWALL_SUMMARY_KEYS(X)                                                                                      \
  X(project) X(frostwall_version) X(closure_time_days) X(front_contact_days) X(thinnest_angle_deg)                     \
  X(wall) X(day) X(OA) X(OB) X(inner) X(outer) X(thickness) X(min_thickness) X(mean_temperature_OB) X(utilisation)     \
  X(isotherm_thickness) X(isotherm_mean_temperature) X(min_thickness_upstream) X(min_thickness_downstream)             \
  X(design) X(required_thickness) X(max_mean_temperature) X(reached_day) X(met_day) X(pass) X(heat_balance)            \
  X(monitoring) X(monitoring_solid) X(interface) X(front) X(front_axis) X(front_along) X(brine) X(wedge) X(pipe_wall)\
  X(run) X(particles) X(steps) X(wall_seconds) X(integrator) X(spacing) X(smoothing_length) X(warnings)                \
  X(groundwater) X(gaps) X(closure_day) X(verdict) X(error_estimate) X(status) X(coarse_closure_days)                  \
  X(sections) X(critical_depth) X(as_built) X(thinnest_wall) X(design_margin) X(intact) X(scenario_directory)          \
  X(layers) X(governing_layer) X(calibration) X(forecast) X(parameters) X(physics) X(soil) X(pores) X(damage)      \
  X(balance) X(thaw_time) X(plant) X(excavation)
// clang-format on

namespace keys {
#define FROSTWALL_SUMMARY_KEY(name) inline constexpr char name[] = #name;
FROSTWALL_SUMMARY_KEYS(FROSTWALL_SUMMARY_KEY)
#undef FROSTWALL_SUMMARY_KEY

// The error of a number sits beside it as "<key>_error".
inline constexpr char error_suffix[] = "_error";
inline std::string error_of(std::string_view key) { return std::string(key) + error_suffix; }

// Every constant above, for the test that holds them against the docs.
inline constexpr std::string_view all[] = {
#define FROSTWALL_SUMMARY_NAME(name) #name,
    FROSTWALL_SUMMARY_KEYS(FROSTWALL_SUMMARY_NAME)
#undef FROSTWALL_SUMMARY_NAME
};
}  // namespace keys

// A frozen stretch along a ray (a wall entry's OA and OB), m.
struct Stretch {
  std::optional<double> inner, outer;  // null where nothing is frozen
  std::optional<double> thickness;
  nlohmann::ordered_json detail = nlohmann::ordered_json::object();
};

// One snapshot's wall: the extent along OA and OB, the thinnest wall; the
// isotherm, flow sides and the wall check's values stay in `detail`.
struct WallEntry {
  std::optional<double> day;
  std::optional<Stretch> OA, OB;
  std::optional<double> min_thickness;        // m, over all rays of the wedge
  std::optional<double> thinnest_angle_deg;   // where the wall is thinnest
  std::optional<double> mean_temperature_OB;  // degC, over the frozen part of OB
  nlohmann::ordered_json detail = nlohmann::ordered_json::object();
};

// The design check: the target and the day it is met.
struct Design {
  std::optional<double> required_thickness;    // m
  std::optional<double> max_mean_temperature;  // degC
  std::optional<double> reached_day, met_day;
  std::optional<bool> pass;
  nlohmann::ordered_json detail = nlohmann::ordered_json::object();
};

// The run's facts (a heat run's "run"); the integrator's statistics and
// the solid's facts stay in `detail`.
struct RunInfo {
  std::optional<std::int64_t> particles, steps;
  std::optional<double> wall_seconds;  // s
  std::optional<std::string> integrator;
  std::optional<double> spacing, smoothing_length;  // m
  nlohmann::ordered_json detail = nlohmann::ordered_json::object();
};

struct Summary {
  std::string project;            // the project's name
  std::string frostwall_version;  // the program's version
  // Days; null when the wall never closes (the columns never touch) within
  // the run; a plain geometry has neither key (see has()).
  std::optional<double> closure_time_days, front_contact_days;
  std::vector<WallEntry> wall;  // one per snapshot (shaft sections)
  std::optional<Design> design;
  std::optional<RunInfo> run;
  std::vector<std::string> warnings;
  // Every other key, in order, with null slots for the typed members'.
  nlohmann::ordered_json detail = nlohmann::ordered_json::object();

  // Whether the summary read has `key` (a typed member's slot or a block).
  bool has(const char* key) const { return detail.contains(key); }
  // An engine's block by its key; null JSON when absent.
  const nlohmann::ordered_json& block(const char* key) const;
};

nlohmann::ordered_json to_json(const Summary& s);
// A number that may be missing, as the summary writes it: the value or null.
inline nlohmann::json number_or_null(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json();
}
Summary from_json(const nlohmann::ordered_json& j);

// The wall entry at `day` (to a relative 1e-9); null if none.
const WallEntry* wall_at(const Summary& s, double day);

}  // namespace frostwall::summary
