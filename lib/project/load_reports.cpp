// The project file's reporting blocks (load_reports.hpp).
#include "project/load_reports.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <string>

namespace frostwall::project::detail {

Design read_design(const Node& n) {
  Design design;
  if (!n.object({"required_thickness", "max_mean_temperature"})) return design;
  design.required_thickness = n["required_thickness"].positive();
  design.max_mean_temperature = n["max_mean_temperature"].number();
  return design;
}

std::vector<Sensor> read_monitoring(const Node& n) {
  std::vector<Sensor> sensors;
  std::map<std::string, std::string> first_path;  // sensor name -> where it was first given
  const std::size_t size = n.array().value_or(0);
  for (std::size_t i = 0; i < size; ++i) {
    const Node e = n[i];
    if (!e.object({"name", "r", "theta_deg", "x", "y"})) continue;
    Sensor sensor;
    const Node name = e["name"].required();
    sensor.name = name.string().value_or("");
    if (!sensor.name.empty()) {
      if (const auto [it, fresh] = first_path.emplace(sensor.name, e.path()); !fresh)
        name.problem("duplicate sensor name '" + sensor.name + "' (also " + it->second + ")");
    }
    const bool polar = e["r"].present() || e["theta_deg"].present();
    const bool cartesian = e["x"].present() || e["y"].present();
    if (polar && cartesian) {
      e.problem("give either r and theta_deg or x and y, not both");
    } else if (polar) {
      const auto r = e["r"].required().non_negative();
      const auto theta = e["theta_deg"].required().number();
      if (r && theta) {
        sensor.x = *r * std::cos(*theta * std::numbers::pi / 180.0);
        sensor.y = *r * std::sin(*theta * std::numbers::pi / 180.0);
      }
    } else if (cartesian) {
      sensor.x = e["x"].required().number().value_or(0.0);
      sensor.y = e["y"].required().number().value_or(0.0);
    } else {
      e.problem("needs a position: r and theta_deg, or x and y");
    }
    sensors.push_back(sensor);
  }
  return sensors;
}

void check_sensors_inside(const Project& project, const Node& n) {
  for (std::size_t i = 0; i < project.monitoring.size(); ++i) {
    const Sensor& s = project.monitoring[i];
    if (const auto* section = std::get_if<ShaftSection>(&project.geometry)) {
      const double r = std::hypot(s.x, s.y), R = section->outer_radius;
      if (R > 0.0 && r > R)
        n[i].problem(fmt::format("r = {:g} m is outside the simulated domain (domain.outer_radius {:g} m)", r, R));
    } else if (const auto* rect = std::get_if<Rectangle>(&project.geometry)) {
      if (s.x < 0.0 || s.x > rect->width || s.y < 0.0 || s.y > rect->height)
        n[i].problem(fmt::format("(x, y) = ({:g}, {:g}) m is outside the rectangle [0, {:g}] x [0, {:g}] m", s.x, s.y,
                                 rect->width, rect->height));
    }
  }
}

namespace {
// [x, y] in metres.
std::optional<std::pair<double, double>> read_point(const Node& n) {
  const auto size = n.required().array();
  if (!size) return std::nullopt;
  if (*size != 2 || !n.json()[0].is_number() || !n.json()[1].is_number()) {
    n.problem("must be a point [x, y] in metres, got " + n.shown());
    return std::nullopt;
  }
  return std::pair{n.json()[0].get<double>(), n.json()[1].get<double>()};
}

}  // namespace

Output read_output(const Node& n) {
  Output output;
  if (!n.object({"directory", "vtk", "full_ring", "report", "front_along"})) return output;
  output.directory = n["directory"].required().string().value_or("");
  output.vtk = n["vtk"].boolean().value_or(true);
  output.full_ring = n["full_ring"].boolean().value_or(true);
  output.report = n["report"].boolean().value_or(true);
  const Node lines = n["front_along"];
  for (std::size_t i = 0; i < lines.array().value_or(0); ++i) {
    const Node line = lines[i];
    if (!line.object({"from", "to"})) continue;
    const auto from = read_point(line["from"]), to = read_point(line["to"]);
    if (!from || !to) continue;
    if (*from == *to) line.problem("from and to must differ");
    output.front_along.push_back({from->first, from->second, to->first, to->second});
  }
  return output;
}

}  // namespace frostwall::project::detail
