// The project file's reporting blocks (load_reports.hpp).
#include "project/load_reports.hpp"

#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <string>

namespace frostwall::project::detail {

// [[T, sigma_c], ...], {"a", "b"} (a + b|T|) or {"sigma_0", "k", "m"}.
std::optional<StrengthLaw> read_strength(const Node& n) {
  if (!n.present()) return std::nullopt;
  if (n.type() == "array") {
    const std::size_t size = n.array().value_or(0);
    std::vector<std::pair<double, double>> points;
    for (std::size_t k = 0; k < size; ++k) {
      const Node point = n[k];
      if (point.array() != std::size_t{2}) {
        point.problem(fmt::format("must be [T, sigma_c], got {}", point.shown()));
        continue;
      }
      const auto T = point[0].number(), sigma = point[1].number();
      if (T && sigma) points.emplace_back(*T, *sigma);
    }
    if (points.size() != size) return std::nullopt;
    if (const std::string why = table_problem(points); !why.empty()) {
      n.problem(why);
      return std::nullopt;
    }
    return StrengthLaw::table(points);
  }
  if (n.type() != "object") {
    n.problem(R"(must be a table [[T, sigma_c], ...], {"a", "b"} or {"sigma_0", "k", "m"})");
    return std::nullopt;
  }
  if (!n.object({"a", "b", "sigma_0", "k", "m"})) return std::nullopt;
  if (n["a"].present() || n["b"].present()) {
    const auto a = n["a"].required().positive(), b = n["b"].required().non_negative();
    if (a && b) return StrengthLaw::linear(*a, *b);
    return std::nullopt;
  }
  const auto s0 = n["sigma_0"].required().non_negative(), k = n["k"].required().positive(),
             m = n["m"].required().positive();
  if (s0 && k && m) return StrengthLaw::power(*s0, *k, *m);
  return std::nullopt;
}

// {"gradient_MPa_per_m"} (times the depth), {"value_MPa"}, or
// {"unit_weight_kN_per_m3", "earth_pressure_coefficient"} (gamma z K).
std::optional<double> read_pressure(const Node& n, std::optional<double> depth, const Node& depth_node) {
  if (!n.object({"gradient_MPa_per_m", "value_MPa", "unit_weight_kN_per_m3", "earth_pressure_coefficient"}))
    return std::nullopt;
  const int given = int(n["gradient_MPa_per_m"].present()) + int(n["value_MPa"].present()) +
                    int(n["unit_weight_kN_per_m3"].present());
  if (given != 1) {
    n.problem(
        R"(give one of "gradient_MPa_per_m", "value_MPa" or "unit_weight_kN_per_m3" (with "earth_pressure_coefficient"))");
    return std::nullopt;
  }
  if (n["value_MPa"].present()) return n["value_MPa"].non_negative();
  if (!depth) {
    depth_node.required().given();  // a pressure growing with depth needs the depth
    return std::nullopt;
  }
  if (const auto g = n["gradient_MPa_per_m"].positive()) return *g * *depth;
  const auto gamma = n["unit_weight_kN_per_m3"].positive(), K = n["earth_pressure_coefficient"].required().positive();
  if (gamma && K) return *gamma * *depth * *K / 1000.0;
  return std::nullopt;
}

Design read_design(const Node& n, bool layered) {
  Design design;
  if (!n.object({"required_thickness", "max_mean_temperature", "strength", "allowable_factor", "depth", "pressure",
                 "formula", "friction_angle", "isotherm"}))
    return design;
  design.required_thickness = n["required_thickness"].positive();
  design.max_mean_temperature = n["max_mean_temperature"].number();
  design.strength = read_strength(n["strength"]);
  design.isotherm = n["isotherm"].number();
  if (const auto f = n["allowable_factor"].number()) {
    if (*f <= 0.0 || *f > 1.0) n["allowable_factor"].problem(fmt::format("must be in (0, 1], got {}", *f));
    else design.allowable_factor = *f;
  }
  if (const auto z = n["depth"].number()) {
    if (*z < 0.0) n["depth"].problem(fmt::format("must not be negative (metres below the surface), got {}", *z));
    else design.depth = z;
  }
  // With layers, each layer's depth serves; the design's own may be left out.
  if (!layered || design.depth || n["pressure"]["value_MPa"].present())
    design.pressure = read_pressure(n["pressure"], design.depth, n["depth"]);
  design.formula = n["formula"]
                       .choice<WallFormula>("formula", {{"domke", WallFormula::domke},
                                                        {"lame_mises", WallFormula::lame_mises},
                                                        {"lame_tresca", WallFormula::lame_tresca},
                                                        {"plastic_mohr_coulomb", WallFormula::plastic_mohr_coulomb},
                                                        {"plastic_tresca", WallFormula::plastic_tresca}})
                       .value_or(design.formula);
  if (const Node phi = n["friction_angle"]; phi.present())
    if (const auto v = phi.non_negative()) {
      if (*v >= 90.0) phi.problem(fmt::format("must be below 90 degrees, got {}", *v));
      else design.friction_angle = v;
    }
  if (design.formula == WallFormula::plastic_mohr_coulomb && !design.friction_angle)
    n["friction_angle"].problem(R"(needed with "formula": "plastic_mohr_coulomb")");
  if (!layered && n["strength"].present() != n["pressure"].present())
    (n["strength"].present() ? n["pressure"] : n["strength"])
        .problem(R"(the wall check needs both "strength" and "pressure")");
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
