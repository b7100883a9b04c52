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
#include "project/load_basics.hpp"
#include "project/load_zones.hpp"
#include "project/load_rectangle.hpp"
#include "project/load_excavation.hpp"
#include "project/load_plant.hpp"
#include "project/load_shaft.hpp"
#include "project/load_calibrate.hpp"
#include "project/load_survey.hpp"
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
using detail::read_rectangle;
using detail::read_side;
using detail::read_soil;
using detail::read_pipe;
using detail::read_layout;
using detail::outermost_pipe_radius;

TimeSettings detail::read_time(const Node& n) {
  TimeSettings time;
  if (!n.object({"end", "unit", "snapshots"})) return time;
  const auto end = n["end"].required().positive();
  time.unit = n["unit"]
                  .required()
                  .choice<TimeUnit>("time unit", {{"s", TimeUnit::s}, {"h", TimeUnit::h}, {"d", TimeUnit::d}})
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

// Defaults that depend on the problem: a shaft section is graded (fine at
// the pipes and through the wall, coarse far out: the same accuracy from a
// third of the particles); the plain rectangles of the verification
// problems keep the lattice. RKL2 steps may change a particle's enthalpy by
// one latent heat (its stages follow the front), an implicit step by a
// quarter (its Newton iteration needs it); bench/README.md has the numbers.
Numerics read_numerics(const Node& n, bool shaft, bool line_sinks) {
  Numerics numerics;
  // Line-sink pipes keep the lattice: its rows stand symmetric about every
  // neck (bench/README.md, "Pipes as line sinks").
  numerics.placement = shaft && !line_sinks ? Placement::graded : Placement::lattice;
  auto default_step_change = [&] {
    if (!n["step_change"].present()) numerics.step_change = numerics.integrator == IntegratorKind::rkl2 ? 1.0 : 0.25;
  };
  if (!n.object({"spacing", "kernel", "smoothing_ratio", "integrator", "beta", "step_change", "conductivity_mean",
                 "laplacian", "symmetry", "placement", "coarsening", "growth", "band_coarsening", "band_width",
                 "max_particles", "method", "horizon", "error_estimate", "sensor_tolerance"})) {
    default_step_change();
    return numerics;
  }
  numerics.spacing = n["spacing"].positive();
  numerics.max_particles = n["max_particles"].positive();
  numerics.error_estimate = n["error_estimate"].boolean().value_or(numerics.error_estimate);
  numerics.kernel = n["kernel"]
                        .choice<KernelKind>("kernel", {{"wendland_c2", KernelKind::wendland_c2},
                                                       {"cubic_spline", KernelKind::cubic_spline}})
                        .value_or(numerics.kernel);
  numerics.smoothing_ratio = n["smoothing_ratio"].positive().value_or(numerics.smoothing_ratio);
  numerics.integrator = n["integrator"]
                            .choice<IntegratorKind>("integrator", {{"explicit", IntegratorKind::explicit_euler},
                                                                   {"implicit", IntegratorKind::implicit},
                                                                   {"rkl2", IntegratorKind::rkl2}})
                            .value_or(numerics.integrator);
  numerics.beta = n["beta"].positive().value_or(numerics.beta);
  numerics.step_change = n["step_change"].positive().value_or(numerics.step_change);
  default_step_change();
  numerics.sensor_tolerance = n["sensor_tolerance"].positive().value_or(numerics.sensor_tolerance);
  numerics.conductivity_mean =
      n["conductivity_mean"]
          .choice<ConductivityMean>("conductivity mean", {{"harmonic", ConductivityMean::harmonic},
                                                          {"arithmetic", ConductivityMean::arithmetic}})
          .value_or(numerics.conductivity_mean);
  numerics.laplacian = n["laplacian"]
                           .choice<LaplacianForm>("laplacian", {{"renormalised", LaplacianForm::renormalised},
                                                                {"plain", LaplacianForm::plain}})
                           .value_or(numerics.laplacian);
  numerics.method =
      n["method"].choice<Method>("method", {{"sph", Method::sph}, {"pd", Method::pd}}).value_or(numerics.method);
  if (const auto h = n["horizon"].positive()) {
    if (*h < 2.0 || *h > 6.0) n["horizon"].problem(fmt::format("must be between 2 and 6 spacings, got {}", *h));
    else numerics.horizon = *h;
  }
  if (numerics.method != Method::pd && n["horizon"].present()) n["horizon"].problem(R"(only used with "method": "pd")");
  const int symmetry = n["symmetry"].choice<int>("symmetry", {{"auto", 0}, {"off", 1}, {"none", 2}}).value_or(0);
  numerics.use_symmetry = symmetry == 0;
  numerics.unsymmetric_cloud = symmetry == 2;
  numerics.placement =
      n["placement"]
          .choice<Placement>("placement", {{"lattice", Placement::lattice}, {"graded", Placement::graded}})
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

// The domain block: the initial temperature; a shaft section's outer
// radius and far field.
void read_domain(const Node& domain, bool shaft, ShaftSection& section, Project& project) {
  if (domain.object({"outer_radius", "initial_temperature", "far_field", "initial_zones"})) {
    project.domain.initial_temperature = domain["initial_temperature"].required().number().value_or(0.0);
    project.domain.initial_zones = detail::read_initial_zones(domain["initial_zones"]);
    if (shaft) {
      const Node outer = domain["outer_radius"].required();
      section.outer_radius = outer.positive().value_or(0.0);
      const double pipes = outermost_pipe_radius(section.layout);
      if (section.outer_radius > 0 && section.outer_radius <= pipes)
        outer.problem(
            fmt::format("must be larger than the outermost pipe's radius {}, got {}", pipes, section.outer_radius));
      // Default: the far field stays at the initial ground temperature.
      project.domain.far_field_temperature = project.domain.initial_temperature;
      if (const Node far = domain["far_field"]; far.present()) {
        std::optional<double> head;
        const bool adiabatic = std::holds_alternative<Adiabatic>(read_side(far, head));
        if (head) far["head"].problem("only used on a rectangle's faces");
        project.domain.far_field_temperature = adiabatic ? std::nullopt : far["temperature"].number();
      }
    }
  }
}

// Water flowing through the ground (shaft sections): the coupled scheme
// (the default) is part of the backward-Euler step, so flowing water
// brings that integrator and its step change. An explicit integrator asked
// for keeps the explicit limited scheme; still water keeps the still-water run.
void read_groundwater_block(const Node& root, bool shaft, Project& project) {
  const auto* rect = std::get_if<Rectangle>(&project.geometry);
  if (rect && rect->has_heads() && !root["groundwater"].present())
    root["geometry"]["boundaries"].problem(
        R"(a face's "head" needs the "groundwater" block (the soil's permeability))");
  if (const Node water = root["groundwater"]; water.present()) {
    if (!shaft && rect && !rect->has_heads())
      water.problem(R"(a rectangle's water flows between faces with a "head" (geometry.boundaries.<face>.head))");
    else if (!shaft && project.numerics.placement == Placement::graded)
      root["numerics"]["placement"].problem(R"(faces with a head need "lattice")");
    else {
      project.groundwater = detail::read_groundwater(water, !shaft);
      auto& g = *project.groundwater;
      if (rect) {
        double lo = 1e300, hi = -1e300;
        for (const auto& h : rect->heads)
          if (h) lo = std::min(lo, *h), hi = std::max(hi, *h);
        g.head_difference = hi - lo;
      }
      const Node numerics = root["numerics"];
      const bool other_integrator = numerics["integrator"].present() &&
                                    project.numerics.integrator != IntegratorKind::implicit;
      if (g.advection == Advection::coupled && other_integrator) {
        if (water["advection"].present())
          water["advection"].problem(R"("coupled" needs "numerics": {"integrator": "implicit"} (or no integrator))");
        g.advection = Advection::limited;
      }
      if (g.flows_coupled()) {
        project.numerics.integrator = IntegratorKind::implicit;
        // A latent heat a step: the step is then held by the run's longest
        // step (a 200th of it) and, while a gap freezes, by the gap's own
        // closure (docs/groundwater.md).
        if (!numerics["step_change"].present()) project.numerics.step_change = 1.0;
      }
      if (g.law.model == PermeabilityModel::constant)
        project.warnings.push_back(
            R"(groundwater.permeability_law: "constant" lets water through frozen ground as through thawed )"
            "(a benchmark's simplification); ice blocks real pores");
      if (shaft)
        project.warnings.push_back(
            "groundwater: a full-size run under flow takes minutes at a 4 cm spacing (projects/seepage_reference.json) "
            "and several times that at the default 2 cm on two cores, and beside frozen ground "
            "the Darcy flux is 7-9 % off (docs/groundwater.md, Limits)");
    }
  }
}

// The wall check, the layers, and the design isotherm (in frozen ground).
void read_design_and_layers(const Node& root, Project& project) {
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
  if (const auto iso = project.design.isotherm) {
    double coldest_freezing = project.soil.freezing_point;
    for (const auto& layer : project.layers) coldest_freezing = std::min(coldest_freezing, layer.soil.freezing_point);
    if (*iso > coldest_freezing)
      root["design"]["isotherm"].problem(
          fmt::format("must be at or below the soil's freezing point ({} degC), got {}", coldest_freezing, *iso));
  }
}

// The shaft as built: failed pipes in any shaft project; a survey and its
// section depths (with compare_intact) on top.
void read_as_built(const Node& root, ShaftSection& section, Project& project, const std::string& base_directory) {
  section.layout.failed_pipes = detail::read_failed_pipes(root["failed_pipes"], section.layout);
  if (const Node c = root["compare_intact"]; c.present()) {
    project.compare_intact = c.boolean().value_or(false);
    if (section.layout.failed_pipes.empty() && project.compare_intact)
      c.problem(R"(needs "failed_pipes" (the scenario to compare with the intact layout))");
  }
  project.survey = detail::read_survey(root["survey"], section.layout, base_directory);
  project.sections = detail::read_sections(root["sections"]);
  if (project.compare_intact && !project.survey && root["layers"].present())
    root["compare_intact"].problem(R"(with "layers", needs "survey" (each section then runs intact beside it))");
  if (root["sections"].present() && !root["survey"].present())
    root["sections"].problem(R"(only used with "survey" (the pipes' positions at depth))");
}

Project read_project(const Node& root, const std::string& base_directory) {
  Project project;
  if (root["physics"].choice<bool>("physics", {{"thermal", false}, {"cfd-dem", true}}).value_or(false)) {
    detail::read_cfd_dem(root, project);
    return project;
  }
  root.object({"name",           "description", "physics",     "layout",   "shaft",     "geometry",   "pipe",
               "soil",           "domain",      "time",        "numerics", "design",    "monitoring", "output",
               "mechanics",      "pore_fluid",  "groundwater", "layers",   "survey",    "sections",   "failed_pipes",
               "compare_intact", "calibrate",   "plant",       "brine",    "excavation"});
  project.name = root["name"].required().string().value_or("");
  project.description = root["description"].string(true).value_or("");

  // A file without "geometry" is taken as a shaft section: the main job.
  const Node layout = root["layout"], geometry = root["geometry"];
  const bool shaft = layout.present() || !geometry.present();
  if (layout.present() && geometry.present()) geometry.problem(R"(give either "layout" or "geometry", not both)");
  if (!layout.present() && !geometry.present())
    layout.problem(
        R"(required field is missing (give "layout" for a shaft section or "geometry" for a plain geometry))");
  ShaftSection section;
  if (layout.present()) section.layout = read_layout(layout);
  if (geometry.present()) {
    Rectangle rectangle = read_rectangle(geometry);
    if (!shaft) project.geometry = std::move(rectangle);
  }
  if (shaft) {
    if (const Node n = root["shaft"]; n.object({"excavation_radius"}))
      section.shaft.excavation_radius = n["excavation_radius"].positive();
    section.pipe = read_pipe(root["pipe"].required(), root["plant"].present());
    read_as_built(root, section, project, base_directory);
  } else {
    for (const char* key : {"survey", "sections", "failed_pipes", "compare_intact"})
      if (root[key].present()) root[key].problem(R"(only used with "layout" (shaft sections))");
  }

  project.soil = read_soil(root["soil"].required(), project.warnings);
  if (shaft && root["pipe"].present())
    detail::warn_warm_pipe(root["pipe"], section.pipe, project.soil.freezing_point, project.warnings);

  const Node domain = root["domain"].required();
  read_domain(domain, shaft, section, project);
  if (shaft) {
    project.geometry = std::move(section);
  } else {
    for (const auto& n : {root["shaft"], root["pipe"], domain["outer_radius"], domain["far_field"]})
      if (n.present()) n.problem(R"(only used with "layout", not with "geometry")");
  }

  project.time = read_time(root["time"].required());
  const auto* shaft_section = std::get_if<ShaftSection>(&project.geometry);
  project.numerics =
      read_numerics(root["numerics"], shaft, shaft_section && shaft_section->pipe.model == PipeModel::line);
  if (const auto* r = std::get_if<Rectangle>(&project.geometry))
    detail::check_rectangle_spacing(root["numerics"]["spacing"], *r, project.numerics.spacing);
  else
    detail::check_shaft_spacing(root["numerics"]["spacing"], std::get<ShaftSection>(project.geometry),
                                project.numerics.spacing);
  if (const double s = project.numerics.smoothing_ratio; s < 1.0 || s > 2.5)
    project.warnings.push_back(
        fmt::format("numerics.smoothing_ratio: {} is outside the usual 1.0..2.5 (too few neighbours below, "
                    "a smeared front above)",
                    s));
  if (project.numerics.method == Method::pd) {
    // The PD bonds use one horizon for the whole cloud, and an isotropic
    // micro-conductivity.
    if (project.numerics.placement == Placement::graded)
      root["numerics"]["method"].problem(R"("pd" needs "placement": "lattice" (one horizon for the whole cloud))");
    if (project.soil.frozen.anisotropic() || project.soil.unfrozen.anisotropic())
      root["numerics"]["method"].problem(R"("pd" needs an isotropic soil (one conductivity per phase))");
    if (const auto* section = std::get_if<ShaftSection>(&project.geometry);
        section && section->pipe.model == PipeModel::line)
      root["numerics"]["method"].problem(
          R"("pd" needs "pipe": {"model": "resolved"} (a line sink is fitted to SPH pairs))");
  }
  if (const Node mech = root["mechanics"]; mech.present()) {
    if (shaft) mech.problem(R"(only used with "geometry" (plain geometries) in this version)");
    else project.mechanics = read_mechanics(mech, project.warnings);
    if (!shaft && project.numerics.placement == Placement::graded)
      mech.problem(R"(needs "placement": "lattice" (one horizon for the whole cloud))");
  }
  read_groundwater_block(root, shaft, project);
  detail::read_pore_settings(root, project);
  read_design_and_layers(root, project);
  project.plant = detail::read_plant(root, project);
  project.excavation = detail::read_excavation(root, project);
  project.monitoring = read_monitoring(root["monitoring"]);
  check_sensors_inside(project, root["monitoring"]);
  project.output = read_output(root["output"].required());
  if (const Node c = root["calibrate"]; c.present()) {
    if (!shaft || !project.layers.empty() || project.survey)
      c.problem(R"(only used with one shaft section ("layout" without "layers" or "survey"))");
    else project.calibration = detail::read_calibration(c, project, base_directory);
  }
  if (!project.output.front_along.empty() && !std::holds_alternative<Rectangle>(project.geometry))
    root["output"]["front_along"].problem(R"(only used with "geometry" (plain geometries))");
  return project;
}

}  // namespace

Project parse_project(const std::string& json_text) { return parse_project(json_text, "project"); }

Project parse_project(const std::string& json_text, const std::string& source) {
  return parse_project(json_text, source, "");
}

Project parse_project(const std::string& json_text, const std::string& source, const std::string& base_directory) {
  std::vector<std::string> problems;
  const auto parsed = detail::parse_document(json_text, source, problems);
  if (!parsed) throw ProjectError(std::move(problems));
  const Json& document = *parsed;
  if (!document.is_object()) throw ProjectError({source + ": must be a JSON object, got " + document.type_name()});

  Project project;
  try {
    project = read_project(Node(&document, "", problems), base_directory);
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
  return parse_project(text.str(), path, fs::path(path).parent_path().string());
}

}  // namespace frostwall::project
