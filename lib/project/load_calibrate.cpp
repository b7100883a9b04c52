// Calibration input (calibrate.hpp): the parameters with their bounds and
// the thermometer readings, read here at the edge and checked against the
// project they calibrate.
#include "project/load_calibrate.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <algorithm>
#include <map>

#include "project/csv_cells.hpp"
#include "project/units.hpp"

namespace frostwall::project {

const char* parameter_name(CalibratedParameter p) {
  switch (p) {
    case CalibratedParameter::conductivity_frozen: return "conductivity_frozen";
    case CalibratedParameter::conductivity_unfrozen: return "conductivity_unfrozen";
    case CalibratedParameter::latent_heat: return "latent_heat";
    case CalibratedParameter::initial_temperature: return "initial_temperature";
    case CalibratedParameter::darcy_flux: return "darcy_flux";
  }
  return "";
}

namespace detail {

namespace {

constexpr CalibratedParameter all_parameters[] = {
    CalibratedParameter::conductivity_frozen, CalibratedParameter::conductivity_unfrozen,
    CalibratedParameter::latent_heat, CalibratedParameter::initial_temperature, CalibratedParameter::darcy_flux};

// The project's own value of a parameter: the fit starts there.
double start_value(CalibratedParameter which, const Project& project) {
  switch (which) {
    case CalibratedParameter::initial_temperature: return project.domain.initial_temperature;
    case CalibratedParameter::darcy_flux:
      return project.groundwater ? project.groundwater->speed() * seconds_per_day : 0.0;
    default: return 1.0;
  }
}

std::vector<FittedParameter> read_parameters(const Node& n, const Project& project) {
  std::vector<FittedParameter> parameters;
  if (!n.required().present()) return parameters;
  if (!n.json().is_object() || n.json().empty()) {
    n.problem("must map at least one parameter to its bounds [low, high], e.g. {\"latent_heat\": [0.5, 2.0]}");
    return parameters;
  }
  std::string expected;
  for (const auto p : all_parameters) expected += (expected.empty() ? "" : ", ") + std::string(parameter_name(p));
  for (const auto& [key, value] : n.json().items()) {
    const Node e = n[key];
    const CalibratedParameter* which = nullptr;
    for (const auto& p : all_parameters)
      if (key == parameter_name(p)) which = &p;
    if (!which) {
      e.problem(fmt::format("unknown parameter '{}' (expected {})", key, expected));
      continue;
    }
    if (*which == CalibratedParameter::darcy_flux && !(project.groundwater && project.groundwater->speed() > 0.0)) {
      e.problem(R"(needs "groundwater" with a flux (its direction is kept, its size fitted))");
      continue;
    }
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
      e.problem("must be bounds [low, high], got " + e.shown());
      continue;
    }
    FittedParameter p{*which, value[0].get<double>(), value[1].get<double>(), start_value(*which, project)};
    const bool factor = *which != CalibratedParameter::initial_temperature && *which != CalibratedParameter::darcy_flux;
    if (!(p.low < p.high)) e.problem(fmt::format("low {} must be below high {}", p.low, p.high));
    else if ((factor || *which == CalibratedParameter::darcy_flux) && p.low < 0.0)
      e.problem(fmt::format("low {} must not be negative", p.low));
    else if (p.start < p.low || p.start > p.high)
      e.problem(fmt::format("bounds [{}, {}] exclude the start value {:g} (the project's own{})", p.low, p.high,
                            p.start, factor ? " value, factor 1" : ""));
    else if (factor && p.low <= 0.0)
      e.problem(fmt::format("low {} must be above 0 (a factor on the soil's value)", p.low));
    parameters.push_back(p);
  }
  return parameters;
}

// The rows of a readings file into `readings`; each problem as "line N: ...".
void read_rows(std::istream& in, const Project& project, std::vector<Reading>& readings,
               std::vector<std::string>& problems) {
  std::string line;
  int number = 0;
  while (std::getline(in, line) && ++number && blank_line(line)) {
  }
  if (split_cells(line) != std::vector<std::string>{"sensor", "time", "temperature"}) {
    problems.push_back(fmt::format("line {}: the header must be sensor,time,temperature, got '{}'", number, line));
    return;
  }
  std::map<std::string, std::size_t> sensors;
  for (std::size_t s = 0; s < project.monitoring.size(); ++s) sensors[project.monitoring[s].name] = s;
  const double unit = project.time.unit_seconds();
  while (std::getline(in, line)) {
    ++number;
    if (blank_line(line)) continue;
    const auto cells = split_cells(line);
    if (cells.size() != 3) {
      problems.push_back(
          fmt::format("line {}: expected 3 cells (sensor,time,temperature), got {}", number, cells.size()));
      continue;
    }
    const bool plant_return = project.plant && cells[0] == "return";
    const auto sensor = sensors.find(cells[0]);
    if (sensor == sensors.end() && !plant_return) {
      problems.push_back(fmt::format("line {}: sensor '{}' is not in \"monitoring\"{}", number, cells[0],
                                     project.plant ? R"( (or "return", the plant's return temperature))" : ""));
      continue;
    }
    const auto time = parse_number(cells[1]), temperature = parse_number(cells[2]);
    if (!time) problems.push_back(fmt::format("line {}: time '{}' is not a number", number, cells[1]));
    if (!temperature) problems.push_back(fmt::format("line {}: temperature '{}' is not a number", number, cells[2]));
    if (!time || !temperature) continue;
    if (*time <= 0.0) {
      problems.push_back(fmt::format("line {}: time {} must be after the start (0)", number, cells[1]));
      continue;
    }
    if (*time * unit > project.time.end * (1 + 1e-12)) {
      problems.push_back(fmt::format("line {}: time {} is after the run's end (time.end {:g} {})", number, cells[1],
                                     project.time.end / unit, project.time.unit_name()));
      continue;
    }
    readings.push_back({number, plant_return ? 0 : sensor->second, *time * unit, *temperature, plant_return});
  }
}

}  // namespace

std::optional<Calibration> read_calibration(const Node& n, const Project& project, const std::string& base_directory) {
  if (!n.present() || !n.object({"readings", "parameters", "noise", "design_day", "step_change"})) return std::nullopt;
  Calibration c;
  c.step_change =
      std::min(n["step_change"].positive().value_or(project.numerics.step_change), project.numerics.step_change);
  c.parameters = read_parameters(n["parameters"], project);
  if (n["noise"].present()) c.noise = n["noise"].positive();
  if (const auto day = n["design_day"].present() ? n["design_day"].positive() : std::nullopt) {
    c.design_time = *day * project.time.unit_seconds();
    if (*c.design_time > project.time.end * (1 + 1e-12))
      n["design_day"].problem(fmt::format("{} is after the run's end (time.end {:g} {})", *day,
                                          project.time.end / project.time.unit_seconds(), project.time.unit_name()));
  }
  const auto file = n["readings"].required().string();
  if (!file) return std::nullopt;
  if (project.monitoring.empty() && !project.plant) {
    n.problem(R"(needs "monitoring" (the sensors whose readings are fitted))");
    return std::nullopt;
  }
  c.file = *file;
  c.path = resolve_path(*file, base_directory);
  std::ifstream in(c.path, std::ios::binary);
  if (!in) {
    n["readings"].problem(fmt::format("cannot read {}: {}", c.path, std::strerror(errno)));
    return std::nullopt;
  }
  std::vector<std::string> problems;
  read_rows(in, project, c.readings, problems);
  for (const auto& p : problems) n["readings"].problem(c.file + " " + p);
  if (problems.empty() && c.readings.size() < c.parameters.size() + 1)
    n["readings"].problem(fmt::format("{}: {} readings cannot fit {} parameters (at least one more reading than "
                                      "parameters is needed)",
                                      c.file, c.readings.size(), c.parameters.size()));
  return c;
}

}  // namespace detail

}  // namespace frostwall::project
