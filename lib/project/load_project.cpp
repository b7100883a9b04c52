// Reads the project file (shared/spec/project-format.md) into the structs of
// project.hpp. Every problem is collected before anything is thrown, so a user
// fixes a file in one round instead of one error per run.
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "project/json_reader.hpp"
#include "project/load_groundwater.hpp"
#include "project/load_cfd_dem.hpp"
#include "project/load_pores.hpp"
#include "project/load_reports.hpp"
#include "project/load_shaft.hpp"
#include "project/project.hpp"

namespace frostwall::project {

using detail::Json;
using detail::Node;
using detail::check_sensors_inside;
using detail::read_design;
using detail::read_monitoring;
using detail::read_output;
using detail::read_time;
using detail::read_schedule;
using detail::read_soil;
using detail::read_pipe;

TimeSettings detail::read_time(const Node& n) {
  TimeSettings time;
  if (!n.object({"end", "unit", "snapshots"})) return time;
  const auto end = n["end"].required().positive();
  time.unit = n["unit"].required().choice<TimeUnit>("time unit", {{"s", TimeUnit::s}, {"h", TimeUnit::h}, {"d", TimeUnit::d}})
                  .value_or(TimeUnit::d);
  const double unit = time.unit_seconds();
  time.end = end.value_or(0.0) * unit;
  const Node snapshots = n["snapshots"];
  if (!snapshots.present()) {
    time.snapshots = {time.end};  // at least the final state
    return time;
  }
  std::optional<double> previous;  // the last accepted snapshot
  const std::size_t size = snapshots.array().value_or(0);
  for (std::size_t i = 0; i < size; ++i) {
    const Node s = snapshots[i];
    const auto t = s.number();
    if (!t) continue;
    if (*t <= 0 || (end && *t > *end)) {
      s.problem(fmt::format("must be after 0 and no later than time.end ({}), got {}", end.value_or(0.0), *t));
    } else if (previous && *t <= *previous) {
      s.problem(fmt::format("must be ascending, got {} after {}", *t, *previous));
    } else {
      time.snapshots.push_back(*t * unit);
      previous = *t;
    }
  }
  return time;
}


namespace {

constexpr double seconds_per_day = 86400.0;
constexpr double pure_water_latent_heat = 334000.0;  // J/kg

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const auto& line : lines) text += (text.empty() ? "" : "\n") + line;
  return text;
}

}  // namespace

// A wall temperature: a number, or [[day, degC], ...] with days ascending.
TemperatureSchedule detail::read_schedule(const Node& n) {
  TemperatureSchedule schedule = TemperatureSchedule::fixed(0.0);
  if (!n.given()) return schedule;
  if (n.json().is_number()) return TemperatureSchedule::fixed(n.json().get<double>());
  if (!n.json().is_array()) {
    n.problem("must be a number or a [[day, degC], ...] schedule, got " + n.type());
    return schedule;
  }
  if (n.json().empty()) {
    n.problem("must have at least one [day, degC] point");
    return schedule;
  }
  schedule.points.clear();
  for (std::size_t i = 0; i < n.json().size(); ++i) {
    const Node point = n[i];
    const Json& p = point.json();
    if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number()) {
      point.problem("must be a [day, degC] pair, got " + (p.is_array() ? point.shown() : point.type()));
      continue;
    }
    const double day = p[0].get<double>();
    const double seconds = day * seconds_per_day;
    if (!schedule.points.empty() && seconds <= schedule.points.back().first)
      point.problem(fmt::format("days must be ascending, got {} after {}", day,
                                schedule.points.back().first / seconds_per_day));
    else
      schedule.points.emplace_back(seconds, p[1].get<double>());
  }
  if (schedule.points.empty()) schedule = TemperatureSchedule::fixed(0.0);
  return schedule;
}

namespace {

// A boundary is "adiabatic" or {"temperature": T}: returns the node of T, or
// nullopt for adiabatic (and for a bad value, which is reported).
std::optional<Node> side_temperature(const Node& n) {
  if (!n.given()) return std::nullopt;
  const std::string expected = R"((expected "adiabatic" or {"temperature": T}))";
  if (n.json().is_string()) {
    const auto name = n.json().get<std::string>();
    if (name != "adiabatic") n.problem("unknown boundary condition '" + name + "' " + expected);
    return std::nullopt;
  }
  if (!n.json().is_object()) {
    n.problem("must be \"adiabatic\" or {\"temperature\": T}, got " + n.type());
    return std::nullopt;
  }
  n.object({"temperature"});
  return n["temperature"].required();
}

SideCondition read_side(const Node& n) {
  if (const auto t = side_temperature(n)) return FixedTemperature{read_schedule(*t)};
  return Adiabatic{};
}

std::array<double, 2> read_conductivity(const Node& n) {
  if (!n.given()) return {};
  if (n.json().is_array()) {
    if (n.json().size() != 2) {
      n.problem(fmt::format("must be a number or [kx, ky], got an array of {}", n.json().size()));
      return {};
    }
    return {n[0].required().positive().value_or(0.0), n[1].required().positive().value_or(0.0)};
  }
  if (!n.json().is_number()) {
    n.problem("must be a number or [kx, ky], got " + n.type());
    return {};
  }
  const double k = n.positive().value_or(0.0);
  return {k, k};
}

}  // namespace

Soil detail::read_soil(const Node& n, std::vector<std::string>& warnings) {
  Soil soil;
  if (!n.given()) return soil;
  if (n.json().is_string()) {
    const auto name = n.json().get<std::string>();
    if (auto builtin = builtin_soil(name)) return *builtin;
    std::string names;
    for (const auto& known : builtin_soil_names()) names += (names.empty() ? "" : ", ") + known;
    n.problem("unknown soil '" + name + "' (built-in: " + names + ")");
    return soil;
  }
  if (!n.json().is_object()) {
    n.problem("must be a built-in soil name or an object, got " + n.type());
    return soil;
  }
  n.object({"name", "density", "unfrozen", "frozen", "latent_heat", "freezing_point", "freezing_range"});
  soil.name = n["name"].string().value_or("custom soil");
  soil.density = n["density"].required().positive().value_or(0.0);
  for (const auto& [key, phase] : {std::pair{"unfrozen", &soil.unfrozen}, std::pair{"frozen", &soil.frozen}}) {
    const Node p = n[key].required();
    if (!p.object({"conductivity", "heat_capacity"})) continue;
    phase->conductivity = read_conductivity(p["conductivity"].required());
    phase->heat_capacity = p["heat_capacity"].required().positive().value_or(0.0);
  }
  // Zero is allowed: a soil without phase change (pure conduction checks).
  soil.latent_heat = n["latent_heat"].required().non_negative().value_or(0.0);
  soil.freezing_point = n["freezing_point"].number().value_or(0.0);
  soil.freezing_range = n["freezing_range"].non_negative().value_or(0.0);
  if (soil.latent_heat > pure_water_latent_heat)
    warnings.push_back(fmt::format(
        "{}: {} J/kg is more than pure water's 334 kJ/kg; probably a slipped decimal point ({}?)",
        n["latent_heat"].path(), soil.latent_heat, soil.latent_heat / 10));
  return soil;
}

namespace {

// A ring of the layout; the angle of its first pipe is `angle_key`.
Ring read_ring(const Node& n, std::string_view angle_key) {
  Ring ring;
  if (!n.object({"radius", "count", angle_key})) return ring;
  ring.radius = n["radius"].required().positive().value_or(0.0);
  ring.count = n["count"].required().count().value_or(0);
  ring.offset_deg = n[angle_key].number().value_or(0.0);
  return ring;
}

Layout read_layout(const Node& n) {
  Layout layout;
  if (!n.object({"pattern", "outer_ring", "inner_ring", "rings", "pipes"})) return layout;
  const Node pattern_node = n["pattern"].required();
  const auto pattern = pattern_node.choice<Pattern>(
      "pattern", {{"single", Pattern::single},
                  {"three-hole", Pattern::three_hole},
                  {"four-hole", Pattern::four_hole},
                  {"rings", Pattern::rings},
                  {"pipes", Pattern::pipes}});
  if (!pattern) return layout;  // which fields belong depends on the pattern
  layout.pattern = *pattern;
  const bool double_ring = *pattern == Pattern::three_hole || *pattern == Pattern::four_hole;
  const bool ring_pattern = double_ring || *pattern == Pattern::single;

  // A field of another pattern is a mistake, not something to ignore.
  const auto uses = [&](std::string_view key) {
    if (key == "outer_ring") return ring_pattern;
    if (key == "inner_ring") return double_ring;
    if (key == "rings") return *pattern == Pattern::rings;
    return *pattern == Pattern::pipes;
  };
  for (const auto key : {"outer_ring", "inner_ring", "rings", "pipes"})
    if (n[key].present() && !uses(key))
      n[key].problem("not used by pattern '" + pattern_node.json().get<std::string>() + "'");

  if (ring_pattern) {
    layout.outer_ring = read_ring(n["outer_ring"].required(), "start_angle_deg");
    if (double_ring) {
      const Node inner = n["inner_ring"].required();
      if (inner.object({"radius"})) layout.inner_ring_radius = inner["radius"].required().positive();
      if (layout.inner_ring_radius && layout.outer_ring.radius > 0 &&
          *layout.inner_ring_radius >= layout.outer_ring.radius)
        inner["radius"].problem(fmt::format("must be smaller than the outer ring's radius {}, got {}",
                                            layout.outer_ring.radius, *layout.inner_ring_radius));
    }
  } else if (*pattern == Pattern::rings) {
    const Node rings = n["rings"].required();
    const auto size = rings.array();
    if (size == 0u) rings.problem("must list at least one ring");
    for (std::size_t i = 0; i < size.value_or(0); ++i)
      layout.rings.push_back(read_ring(rings[i], "offset_deg"));
  } else {
    const Node pipes = n["pipes"].required();
    const auto size = pipes.array();
    if (size == 0u) pipes.problem("must list at least one pipe");
    for (std::size_t i = 0; i < size.value_or(0); ++i) {
      const Node p = pipes[i];
      if (!p.object({"x", "y"})) continue;
      layout.pipes.push_back({p["x"].required().number().value_or(0.0), p["y"].required().number().value_or(0.0)});
    }
  }
  return layout;
}

// Distance of the farthest pipe centre from the shaft axis.
double outermost_pipe_radius(const Layout& layout) {
  double r = layout.outer_ring.radius;
  for (const auto& ring : layout.rings) r = std::max(r, ring.radius);
  for (const auto& p : layout.pipes) r = std::max(r, std::hypot(p.x, p.y));
  return r;
}

Rectangle read_rectangle(const Node& n) {
  Rectangle rectangle;
  if (!n.object({"type", "width", "height", "boundaries", "pores"})) return rectangle;
  n["type"].required().choice<int>("geometry type", {{"rectangle", 0}});
  rectangle.width = n["width"].required().positive().value_or(0.0);
  rectangle.height = n["height"].required().positive().value_or(0.0);
  detail::read_pores(n["pores"], rectangle);
  const Node sides = n["boundaries"].required();
  if (!sides.object({"left", "right", "top", "bottom"})) return rectangle;
  for (const auto& [key, side] : {std::pair{"left", &rectangle.left}, std::pair{"right", &rectangle.right},
                                  std::pair{"top", &rectangle.top}, std::pair{"bottom", &rectangle.bottom}})
    *side = read_side(sides[key].required());
  return rectangle;
}


// Defaults that depend on the problem: a shaft section is graded (fine at
// the pipes and through the wall, coarse far out: the same accuracy from a
// third of the particles); the plain rectangles of the verification
// problems keep the lattice. RKL2 steps may change a particle's enthalpy by
// one latent heat (its stages follow the front), an implicit step by a
// quarter (its Newton iteration needs it); bench/README.md has the numbers.
Numerics read_numerics(const Node& n, bool shaft) {
  Numerics numerics;
  numerics.placement = shaft ? Placement::graded : Placement::lattice;
  auto default_step_change = [&] {
    if (!n["step_change"].present()) numerics.step_change = numerics.integrator == IntegratorKind::rkl2 ? 1.0 : 0.25;
  };
  if (!n.object({"spacing", "kernel", "smoothing_ratio", "integrator", "beta", "step_change", "conductivity_mean",
                 "laplacian", "symmetry", "placement", "coarsening", "growth", "band_coarsening", "band_width",
                 "max_particles", "method", "horizon"})) {
    default_step_change();
    return numerics;
  }
  numerics.spacing = n["spacing"].positive();
  numerics.max_particles = n["max_particles"].positive();
  numerics.kernel = n["kernel"].choice<KernelKind>(
      "kernel", {{"wendland_c2", KernelKind::wendland_c2}, {"cubic_spline", KernelKind::cubic_spline}})
                        .value_or(numerics.kernel);
  numerics.smoothing_ratio = n["smoothing_ratio"].positive().value_or(numerics.smoothing_ratio);
  numerics.integrator = n["integrator"].choice<IntegratorKind>(
      "integrator", {{"explicit", IntegratorKind::explicit_euler},
                     {"implicit", IntegratorKind::implicit},
                     {"rkl2", IntegratorKind::rkl2}})
                            .value_or(numerics.integrator);
  numerics.beta = n["beta"].positive().value_or(numerics.beta);
  numerics.step_change = n["step_change"].positive().value_or(numerics.step_change);
  default_step_change();
  numerics.conductivity_mean = n["conductivity_mean"].choice<ConductivityMean>(
      "conductivity mean", {{"harmonic", ConductivityMean::harmonic}, {"arithmetic", ConductivityMean::arithmetic}})
                                   .value_or(numerics.conductivity_mean);
  numerics.laplacian = n["laplacian"].choice<LaplacianForm>(
      "laplacian", {{"renormalised", LaplacianForm::renormalised}, {"plain", LaplacianForm::plain}})
                           .value_or(numerics.laplacian);
  numerics.method = n["method"].choice<Method>("method", {{"sph", Method::sph}, {"pd", Method::pd}})
                        .value_or(numerics.method);
  if (const auto h = n["horizon"].positive()) {
    if (*h < 2.0 || *h > 6.0) n["horizon"].problem(fmt::format("must be between 2 and 6 spacings, got {}", *h));
    else numerics.horizon = *h;
  }
  if (numerics.method != Method::pd && n["horizon"].present()) n["horizon"].problem(R"(only used with "method": "pd")");
  numerics.use_symmetry = n["symmetry"].choice<bool>("symmetry", {{"auto", true}, {"off", false}})
                              .value_or(numerics.use_symmetry);
  numerics.placement = n["placement"].choice<Placement>(
      "placement", {{"lattice", Placement::lattice}, {"graded", Placement::graded}})
                           .value_or(numerics.placement);
  // The grading: only with placement "graded" (a lattice would ignore it).
  Grading& g = numerics.grading;
  const Node coarsening = n["coarsening"], growth = n["growth"], band = n["band_coarsening"], width = n["band_width"];
  if (numerics.placement != Placement::graded) {
    for (const auto& field : {coarsening, growth, band, width})
      if (field.present()) field.problem(R"(only used with "placement": "graded")");
    return numerics;
  }
  if (const auto c = coarsening.number()) {
    if (*c < 1.0) coarsening.problem(fmt::format("must be at least 1 (coarsest / finest spacing), got {}", *c));
    else g.coarsening = *c;
  }
  if (const auto r = growth.number()) {
    if (*r <= 1.0 || *r > 2.0)
      growth.problem(fmt::format("must be above 1 and at most 2 (ratio of neighbouring spacings), got {}", *r));
    else g.growth = *r;
  }
  if (const auto b = band.number()) {
    if (*b < 1.0 || *b > g.coarsening)
      band.problem(fmt::format("must be between 1 and numerics.coarsening ({}), got {}", g.coarsening, *b));
    else g.band_coarsening = *b;
  } else if (g.band_coarsening > g.coarsening) {
    g.band_coarsening = g.coarsening;  // the default band never coarser than the far field
  }
  g.band_width = width.non_negative();
  return numerics;
}

Project read_project(const Node& root) {
  Project project;
  if (root["physics"].choice<bool>("physics", {{"thermal", false}, {"cfd-dem", true}}).value_or(false)) {
    detail::read_cfd_dem(root, project);
    return project;
  }
  root.object({"name", "description", "physics", "layout", "shaft", "geometry", "pipe", "soil", "domain", "time",
               "numerics", "design", "monitoring", "output", "mechanics", "pore_fluid", "groundwater", "layers"});
  project.name = root["name"].required().string().value_or("");
  project.description = root["description"].string(true).value_or("");

  // A file without "geometry" is taken as a shaft section: the main job.
  const Node layout = root["layout"], geometry = root["geometry"];
  const bool shaft = layout.present() || !geometry.present();
  if (layout.present() && geometry.present()) geometry.problem(R"(give either "layout" or "geometry", not both)");
  if (!layout.present() && !geometry.present())
    layout.problem(R"(required field is missing (give "layout" for a shaft section or "geometry" for a plain geometry))");
  ShaftSection section;
  if (layout.present()) section.layout = read_layout(layout);
  if (geometry.present()) {
    Rectangle rectangle = read_rectangle(geometry);
    if (!shaft) project.geometry = std::move(rectangle);
  }
  if (shaft) {
    if (const Node n = root["shaft"]; n.object({"excavation_radius"}))
      section.shaft.excavation_radius = n["excavation_radius"].positive();
    section.pipe = read_pipe(root["pipe"].required());
  }

  project.soil = read_soil(root["soil"].required(), project.warnings);
  if (shaft && root["pipe"].present())
    detail::warn_warm_pipe(root["pipe"], section.pipe, project.soil.freezing_point, project.warnings);

  const Node domain = root["domain"].required();
  if (domain.object({"outer_radius", "initial_temperature", "far_field"})) {
    project.domain.initial_temperature = domain["initial_temperature"].required().number().value_or(0.0);
    if (shaft) {
      const Node outer = domain["outer_radius"].required();
      section.outer_radius = outer.positive().value_or(0.0);
      const double pipes = outermost_pipe_radius(section.layout);
      if (section.outer_radius > 0 && section.outer_radius <= pipes)
        outer.problem(fmt::format("must be larger than the outermost pipe's radius {}, got {}", pipes,
                                  section.outer_radius));
      // Default: the far field stays at the initial ground temperature.
      project.domain.far_field_temperature = project.domain.initial_temperature;
      if (const Node far = domain["far_field"]; far.present()) {
        const auto t = side_temperature(far);
        project.domain.far_field_temperature = t ? t->number() : std::nullopt;
      }
    }
  }
  if (shaft) {
    project.geometry = std::move(section);
  } else {
    for (const auto& n : {root["shaft"], root["pipe"], domain["outer_radius"], domain["far_field"]})
      if (n.present()) n.problem(R"(only used with "layout", not with "geometry")");
  }

  project.time = read_time(root["time"].required());
  project.numerics = read_numerics(root["numerics"], shaft);
  if (const double s = project.numerics.smoothing_ratio; s < 1.0 || s > 2.5)
    project.warnings.push_back(fmt::format(
        "numerics.smoothing_ratio: {} is outside the usual 1.0..2.5 (too few neighbours below, "
        "a smeared front above)",
        s));
  if (project.numerics.method == Method::pd) {
    // The PD bonds use one horizon for the whole cloud, and an isotropic
    // micro-conductivity.
    if (project.numerics.placement == Placement::graded)
      root["numerics"]["method"].problem(R"("pd" needs "placement": "lattice" (one horizon for the whole cloud))");
    if (project.soil.frozen.anisotropic() || project.soil.unfrozen.anisotropic())
      root["numerics"]["method"].problem(R"("pd" needs an isotropic soil (one conductivity per phase))");
  }
  if (const Node mech = root["mechanics"]; mech.present()) {
    if (shaft) mech.problem(R"(only used with "geometry" (plain geometries) in this version)");
    else project.mechanics = read_mechanics(mech, project.warnings);
    if (!shaft && project.numerics.placement == Placement::graded)
      mech.problem(R"(needs "placement": "lattice" (one horizon for the whole cloud))");
  }
  if (const Node water = root["groundwater"]; water.present()) {
    if (!shaft) water.problem(R"(only used with "shaft" sections in this version)");
    else {
      project.groundwater = detail::read_groundwater(water);
      // The coupled scheme (the default) is part of the backward-Euler step:
      // flowing water brings that integrator and its step change. An
      // explicit integrator asked for keeps the explicit limited scheme;
      // still water keeps the still-water run.
      auto& g = *project.groundwater;
      const Node numerics = root["numerics"];
      const bool other_integrator = numerics["integrator"].present() && project.numerics.integrator != IntegratorKind::implicit;
      if (g.advection == Advection::coupled && other_integrator) {
        if (water["advection"].present())
          water["advection"].problem(R"("coupled" needs "numerics": {"integrator": "implicit"} (or no integrator))");
        g.advection = Advection::limited;
      }
      if (g.advection == Advection::coupled && g.speed() > 0.0) {
        project.numerics.integrator = IntegratorKind::implicit;
        if (!numerics["step_change"].present()) project.numerics.step_change = 0.25;
      }
      project.warnings.push_back(
          "groundwater: the coupling is new (issue 17 in progress): beside frozen ground the flow is 7-9 % off, "
          "not the 2 % asked, and a full-size run takes more than an hour (the coupled step's Newton "
          "iterations on the half section the flow leaves)");
    }
  }
  detail::read_pore_settings(root, project);
  project.design = read_design(root["design"], root["layers"].present());
  if (project.design.strength) {
    const auto* section = std::get_if<ShaftSection>(&project.geometry);
    if (!section) root["design"]["strength"].problem("only used with shaft sections (the wall round an excavation)");
    else if (!section->shaft.excavation_radius)
      root["design"]["strength"].problem(R"(needs "shaft": {"excavation_radius"} (the formulas' a))");
  }
  project.layers = detail::read_layers(root["layers"], root, project);
  if (const auto* section = std::get_if<ShaftSection>(&project.geometry);
      section && !project.layers.empty() && !section->shaft.excavation_radius)
    root["layers"].problem(R"(the layers' wall checks need "shaft": {"excavation_radius"} (the formulas' a))");
  // The design isotherm lies in frozen ground (colder than freezing).
  if (const auto iso = project.design.isotherm) {
    double coldest_freezing = project.soil.freezing_point;
    for (const auto& layer : project.layers) coldest_freezing = std::min(coldest_freezing, layer.soil.freezing_point);
    if (*iso > coldest_freezing)
      root["design"]["isotherm"].problem(
          fmt::format("must be at or below the soil's freezing point ({} degC), got {}", coldest_freezing, *iso));
  }
  project.monitoring = read_monitoring(root["monitoring"]);
  check_sensors_inside(project, root["monitoring"]);
  project.output = read_output(root["output"].required());
  if (!project.output.front_along.empty() && !std::holds_alternative<Rectangle>(project.geometry))
    root["output"]["front_along"].problem(R"(only used with "geometry" (plain geometries))");
  return project;
}

}  // namespace

ProjectError::ProjectError(std::vector<std::string> problems)
    : std::runtime_error(join(problems)), problems_(std::move(problems)) {}

Project parse_project(const std::string& json_text) { return parse_project(json_text, "project"); }

Project parse_project(const std::string& json_text, const std::string& source) {
  Json document;
  try {
    document = Json::parse(json_text);
  } catch (const Json::exception& e) {
    // parse_error, or out_of_range for a number like 1e400. Drop the library's
    // "[json.exception.parse_error.101] " tag; keep line and column.
    std::string message = e.what();
    if (const auto tag_end = message.find("] "); message.starts_with("[json.exception") && tag_end != std::string::npos)
      message.erase(0, tag_end + 2);
    throw ProjectError({source + ": not valid JSON: " + message});
  }
  if (!document.is_object()) throw ProjectError({source + ": must be a JSON object, got " + document.type_name()});

  std::vector<std::string> problems;
  Project project;
  try {
    project = read_project(Node(&document, "", problems));
  } catch (const Json::exception& e) {
    // The readers check types before converting; this is only a safety net so
    // that bad content can never escape as anything but a ProjectError.
    problems.push_back(source + ": " + e.what());
  }
  if (!problems.empty()) throw ProjectError(std::move(problems));
  return project;
}

Project load_project(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw ProjectError({path + ": cannot read: is a directory, not a project file"});
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ProjectError({path + ": cannot read: " + std::strerror(errno)});
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ProjectError({path + ": cannot read: " + std::strerror(errno)});
  return parse_project(text.str(), path);
}

}  // namespace frostwall::project
