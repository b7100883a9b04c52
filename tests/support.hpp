// Small helpers shared by the verification tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <string>
#include <vector>

#include "project/project.hpp"
#include "freezing/model.hpp"
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
std::size_t march(freezing::Model& m, const std::vector<double>& times, At&& at) {
  thermal::TimeLoopObservers obs;
  obs.snapshot = [&](const thermal::ThermalModel&, double, std::size_t k) { at(k); };
  return thermal::run_time_loop(*m.model, *m.integrator, times.back(), times, obs).steps;
}

// Largest |T - exact| at t = 0.05 of the mode cos(pi x) cos(pi y) on the
// insulated unit square (5 + mode at t = 0, no latent heat), which decays
// as exp(-2 pi^2 t); numerics: the project's "numerics" (JSON).
inline double insulated_sine_mode_error(const std::string& numerics) {
  const double t_end = 0.05;
  const std::string insulated =
      R"({ "left": "adiabatic", "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })";
  auto m = freezing::build_model(rectangle_project(1.0, 1.0, insulated, unit_soil(-100.0, 0.0), 5.0, t_end, numerics));
  const auto& x = m.particles().position;
  auto mode = [&](std::size_t i) { return std::cos(M_PI * x[i][0]) * std::cos(M_PI * x[i][1]); };
  for (std::size_t i = 0; i < m.model->free_count(); ++i)
    m.model->set_enthalpy(i, m.model->law().enthalpy(5.0 + mode(i)));
  double error = 0.0;
  march(m, {t_end}, [&](std::size_t) {
    const double decay = std::exp(-2.0 * M_PI * M_PI * t_end);
    for (std::size_t i = 0; i < m.model->free_count(); ++i)
      error = std::max(error, std::abs(m.model->temperature()[i] - (5.0 + decay * mode(i))));
  });
  return error;
}

// The half-space x > 0 at 1, its face held at 0 from t = 0 (a strip two
// rows high, 1 long, no latent heat): the largest |T - erf(x / (2 sqrt t))|
// at t = 0.02 (the far end stays at 1); numerics as above.
inline double cooled_half_space_error(double dx, const std::string& numerics) {
  const double t_end = 0.02;
  auto m = freezing::build_model(rectangle_project(
      1.0, 2 * dx,
      R"({ "left": { "temperature": 0.0 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
      unit_soil(-100.0, 0.0), 1.0, t_end, numerics));
  double error = 0.0;
  march(m, {t_end}, [&](std::size_t) {
    for (std::size_t i = 0; i < m.model->free_count(); ++i) {
      const double x = m.particles().position[i][0];
      error = std::max(error, std::abs(m.model->temperature()[i] - std::erf(x / (2.0 * std::sqrt(t_end)))));
    }
  });
  return error;
}

// Observed order of convergence between successive halvings.
inline double observed_order(double coarse_error, double fine_error) { return std::log2(coarse_error / fine_error); }

}  // namespace frostwall::test

#include <fstream>
#include <nlohmann/json.hpp>

#include "freezing/closure_tracker.hpp"
#include "paths.hpp"

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
inline ClosureDays closure_days(freezing::Model& m, double t_end, std::vector<double> snapshots = {}) {
  if (snapshots.empty() || snapshots.back() < t_end) snapshots.push_back(t_end);
  freezing::ClosureTracker tracker(m, t_end, t_end / freezing::time_series_points);
  thermal::TimeLoopObservers obs;
  obs.after_step = [&](const thermal::ThermalModel& model, double t) { tracker.after_step(model, t); };
  obs.finished = [&] { return tracker.closure_time().has_value(); };
  thermal::run_time_loop(*m.model, *m.integrator, t_end, snapshots, obs);
  auto days = [](const std::optional<double>& t) { return t ? std::optional(*t / 86400.0) : std::nullopt; };
  return {days(tracker.closure_time()), days(tracker.contact_time())};
}
inline std::optional<double> closure_day(freezing::Model& m, double t_end) { return closure_days(m, t_end).closure; }

}  // namespace frostwall::test
