// Small helpers shared by the verification tests.
#pragma once

#include <cmath>
#include <fmt/core.h>
#include <string>
#include <vector>

#include "project/project.hpp"
#include "run/model.hpp"
#include "thermal/time_loop.hpp"

namespace frostwall::test {

// A rectangle project from its parts (JSON snippets), read by the real loader.
inline project::Project rectangle_project(double width, double height, const std::string& boundaries,
                                          const std::string& soil, double initial, double end_s,
                                          const std::string& numerics) {
  const std::string text = fmt::format(R"({{
    "name": "test", "geometry": {{ "type": "rectangle", "width": {}, "height": {}, "boundaries": {} }},
    "soil": {}, "domain": {{ "initial_temperature": {} }},
    "time": {{ "end": {}, "unit": "s", "snapshots": [{}] }},
    "numerics": {}, "output": {{ "directory": "unused" }} }})",
                                       width, height, boundaries, soil, initial, end_s, end_s, numerics);
  return project::parse_project(text);
}

// A soil with unit properties; freezing point and latent heat as given.
inline std::string unit_soil(double freezing_point, double latent_heat) {
  return fmt::format(R"({{ "name": "unit", "density": 1, "unfrozen": {{ "conductivity": 1, "heat_capacity": 1 }},
      "frozen": {{ "conductivity": 1, "heat_capacity": 1 }}, "latent_heat": {}, "freezing_point": {} }})",
                     latent_heat, freezing_point);
}

inline std::string numerics(double spacing, const std::string& laplacian = "renormalised",
                            const std::string& integrator = "explicit", double step_change = 0.25) {
  return fmt::format(R"({{ "spacing": {}, "integrator": "{}", "laplacian": "{}", "step_change": {} }})", spacing,
                     integrator, laplacian, step_change);
}

// Marches to each time in `times`, calling at(k) there.
template <class At>
std::size_t march(run::Model& m, const std::vector<double>& times, At&& at) {
  thermal::TimeLoopObservers obs;
  obs.snapshot = [&](const thermal::ThermalModel&, double, std::size_t k) { at(k); };
  return thermal::run_time_loop(*m.model, *m.integrator, times.back(), times, obs).steps;
}

// Observed order of convergence between successive halvings.
inline double observed_order(double coarse_error, double fine_error) { return std::log2(coarse_error / fine_error); }

}  // namespace frostwall::test

#include <fstream>
#include <nlohmann/json.hpp>

#include "run/closure_tracker.hpp"

namespace frostwall::test {

// A shipped project with a JSON merge patch applied (the loader reads it).
inline project::Project shipped_project(const std::string& name, const nlohmann::json& patch) {
  std::ifstream in(std::string(FROSTWALL_SOURCE_DIR) + "/projects/" + name);
  nlohmann::json j = nlohmann::json::parse(in);
  j.merge_patch(patch);
  return project::parse_project(j.dump());
}

// Closure (a fully frozen path) and front contact (liquid fraction 0.5)
// days of a shaft model, interpolated between steps as run_project does;
// the run stops at closure or at t_end.
struct ClosureDays {
  std::optional<double> closure, contact;
};
// snapshots: where the run lands exactly (a shipped project's snapshot
// days cut its steps as in `frostwall run`); t_end is always one.
inline ClosureDays closure_days(run::Model& m, double t_end, std::vector<double> snapshots = {}) {
  if (snapshots.empty() || snapshots.back() < t_end) snapshots.push_back(t_end);
  run::ClosureTracker tracker(m, t_end, t_end / run::time_series_points);
  thermal::TimeLoopObservers obs;
  obs.after_step = [&](const thermal::ThermalModel& model, double t) { tracker.after_step(model, t); };
  obs.finished = [&] { return tracker.closure_time().has_value(); };
  thermal::run_time_loop(*m.model, *m.integrator, t_end, snapshots, obs);
  auto days = [](const std::optional<double>& t) { return t ? std::optional(*t / 86400.0) : std::nullopt; };
  return {days(tracker.closure_time()), days(tracker.contact_time())};
}
inline std::optional<double> closure_day(run::Model& m, double t_end) { return closure_days(m, t_end).closure; }

}  // namespace frostwall::test
