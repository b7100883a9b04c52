// The freeze pipe and the layers of a shaft section (load_shaft.hpp).
#include "project/load_shaft.hpp"

#include <fmt/format.h>
#include <cmath>
#include <set>

#include "project/load_reports.hpp"

namespace frostwall::project::detail {

namespace {

// {"inner_diameter", "outer_diameter", "flow_m3_per_h", "brine": {"density",
// "viscosity", "conductivity", "heat_capacity"}}; nullopt on any problem.
std::optional<Annulus> read_annulus(const Node& n, double pipe_diameter) {
  if (!n.object({"inner_diameter", "outer_diameter", "flow_m3_per_h", "brine"})) return std::nullopt;
  Annulus a;
  const auto di = n["inner_diameter"].required().positive(), d_o = n["outer_diameter"].required().positive();
  const auto flow = n["flow_m3_per_h"].required().positive();
  const Node b = n["brine"].required();
  bool ok = di && d_o && flow;
  if (d_o && *d_o >= pipe_diameter)
    n["outer_diameter"].problem(fmt::format(
        "must be below the pipe's diameter {} (the freeze pipe's inner diameter), got {}", pipe_diameter, *d_o)),
        ok = false;
  if (di && d_o && *di >= *d_o)
    n["inner_diameter"].problem(
        fmt::format("must be below outer_diameter {} (the supply pipe inside the freeze pipe), got {}", *d_o, *di)),
        ok = false;
  if (!b.object({"density", "viscosity", "conductivity", "heat_capacity"})) return std::nullopt;
  const auto rho = b["density"].required().positive(), mu = b["viscosity"].required().positive();
  const auto k = b["conductivity"].required().positive(), cp = b["heat_capacity"].required().positive();
  if (!ok || !rho || !mu || !k || !cp) return std::nullopt;
  a.inner_diameter = *di, a.outer_diameter = *d_o, a.flow = *flow / 3600.0;
  a.brine = {*rho, *mu, *k, *cp};
  return a;
}

// A ring of the layout; the angle of its first pipe is `angle_key`.
Ring read_ring(const Node& n, std::string_view angle_key) {
  Ring ring;
  if (!n.object({"radius", "count", angle_key})) return ring;
  ring.radius = n["radius"].required().positive().value_or(0.0);
  ring.count = n["count"].required().count().value_or(0);
  ring.offset_deg = n[angle_key].number().value_or(0.0);
  return ring;
}

}  // namespace

Layout read_layout(const Node& n) {
  Layout layout;
  if (!n.object({"pattern", "outer_ring", "inner_ring", "rings", "pipes"})) return layout;
  const Node pattern_node = n["pattern"].required();
  const auto pattern = pattern_node.choice<Pattern>("pattern", {{"single", Pattern::single},
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
    for (std::size_t i = 0; i < size.value_or(0); ++i) layout.rings.push_back(read_ring(rings[i], "offset_deg"));
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

Pipe read_pipe(const Node& n, bool plant) {
  Pipe pipe;
  if (!n.object({"diameter", "temperature", "model", "boundary", "brine_temperature", "heat_transfer_coefficient",
                 "annulus", "heat_extraction", "inner_diameter", "wall_thickness", "wall_conductivity",
                 "inner_wall_thickness", "inner_wall_conductivity", "length"}))
    return pipe;
  pipe.diameter = n["diameter"].required().positive().value_or(0.0);
  pipe.model = n["model"]
                   .choice<PipeModel>("pipe model", {{"disc", PipeModel::disc},
                                                     {"resolved", PipeModel::disc},
                                                     {"line", PipeModel::line},
                                                     {"point", PipeModel::point}})
                   .value_or(PipeModel::disc);
  pipe.boundary =
      n["boundary"]
          .choice<PipeBoundary>("pipe boundary", {{"fixed", PipeBoundary::fixed}, {"brine", PipeBoundary::brine}})
          .value_or(PipeBoundary::fixed);
  if (plant) {
    // The plant's brine behind the coaxial pipe's film; the circuit sets both.
    for (const char* key :
         {"temperature", "brine_temperature", "heat_transfer_coefficient", "annulus", "heat_extraction"})
      if (n[key].present()) n[key].problem(R"(not used with "plant" (the brine comes from the plant's circuit))");
    if (n["boundary"].present() && pipe.boundary != PipeBoundary::brine)
      n["boundary"].problem(R"(with "plant" the pipe holds brine behind its film ("brine"))");
    pipe.boundary = PipeBoundary::brine;
    pipe.temperature = TemperatureSchedule::fixed(0.0);
    pipe.heat_transfer_coefficient = 1.0;
    return pipe;
  }
  if (n["heat_extraction"].present()) {
    // The plant's view: the heat each pipe draws, its wall's temperature computed.
    for (const char* key : {"temperature", "brine_temperature", "heat_transfer_coefficient", "annulus"})
      if (n[key].present()) n[key].problem(R"(not used with "heat_extraction" (the wall's temperature is computed))");
    if (pipe.boundary == PipeBoundary::brine)
      n["boundary"].problem(
          R"(not used with "heat_extraction" (the heat drawn is given, not the brine's temperature))");
    pipe.heat_extraction = true;
    pipe.temperature = read_schedule(n["heat_extraction"], "W/m");
    if (pipe.model == PipeModel::point)
      n["heat_extraction"].problem(R"(needs "model": "line" or "disc" (the wall the heat is drawn through))");
    return pipe;
  }
  if (pipe.boundary == PipeBoundary::fixed) {
    pipe.temperature = read_schedule(n["temperature"].required());
    for (const char* key : {"brine_temperature", "heat_transfer_coefficient", "annulus"})
      if (n[key].present()) n[key].problem(R"(only used with "boundary": "brine")");
    return pipe;
  }
  // Brine: the schedule is the brine's; the wall's temperature follows from
  // the heat the ground gives up through the film.
  if (n["temperature"].present())
    n["temperature"].problem(
        R"(with "boundary": "brine" the pipe wall's temperature is computed; give "brine_temperature")");
  pipe.temperature = read_schedule(n["brine_temperature"].required());
  if (n["annulus"].present() == n["heat_transfer_coefficient"].present())
    n["heat_transfer_coefficient"].problem(R"(give either "heat_transfer_coefficient" or "annulus" (h from the flow))");
  else if (n["annulus"].present()) pipe.annulus = read_annulus(n["annulus"], pipe.diameter);
  else pipe.heat_transfer_coefficient = n["heat_transfer_coefficient"].positive().value_or(0.0);
  if (pipe.model == PipeModel::point)
    n["boundary"].problem(R"("brine" needs "model": "line" or "disc" (a film needs the pipe's wall))");
  return pipe;
}

void warn_warm_pipe(const Node& n, const Pipe& pipe, double freezing_point, std::vector<std::string>& warnings) {
  if (pipe.heat_extraction) return;
  const Node temperature = n[pipe.boundary == PipeBoundary::brine ? "brine_temperature" : "temperature"];
  if (!temperature.present()) return;
  const bool is_schedule = temperature.json().is_array();
  const char* what = pipe.boundary == PipeBoundary::brine ? "brine" : "pipe";
  for (std::size_t i = 0; i < pipe.temperature.points.size(); ++i)
    if (const double t = pipe.temperature.points[i].second; t > freezing_point)
      warnings.push_back(fmt::format("{}: {} degC is above the soil's freezing point ({} degC); "
                                     "a {} this warm cannot freeze the ground",
                                     is_schedule ? temperature[i].path() : temperature.path(), t, freezing_point,
                                     what));
}

std::vector<Layer> read_layers(const Node& n, const Node& root, const Project& project) {
  std::vector<Layer> layers;
  if (!n.present()) return layers;
  const std::size_t size = n.array().value_or(0);
  if (n.type() == "array" && size == 0) n.problem("must list at least one layer");
  if (size > 0 && !std::holds_alternative<ShaftSection>(project.geometry))
    n.problem("only used with shaft sections (one cross-section per layer)");
  if (size > 0 && !project.design.strength && !root["design"]["strength"].present()) {
    // Each layer may bring its own strength; the check needs one for every layer.
    for (std::size_t k = 0; k < size; ++k)
      if (n[k].type() == "object" && !n[k]["strength"].present())
        n[k]["strength"].problem(R"(required (the layer's wall check; "design" gives no strength))");
  }
  std::set<std::string> names;
  std::vector<std::string> ignored;  // a layer's soil warnings repeat the project's
  for (std::size_t k = 0; k < size; ++k) {
    const Node l = n[k];
    if (!l.object({"name", "depth", "soil", "pressure", "strength"})) continue;
    Layer layer;
    layer.name = l["name"].required().string().value_or("");
    if (!layer.name.empty() && !names.insert(layer.name).second)
      l["name"].problem(fmt::format("'{}' names two layers", layer.name));
    const auto depth = l["depth"].required().number();
    if (depth && *depth < 0.0)
      l["depth"].problem(fmt::format("must not be negative (metres below the surface), got {}", *depth));
    layer.depth = depth.value_or(0.0);
    layer.soil = l["soil"].present() ? read_soil(l["soil"], ignored) : project.soil;
    if (l["strength"].present()) read_strength(l["strength"]);  // checked here; the layer's run reads it from the patch
    if (l["pressure"].present()) {
      layer.pressure = read_pressure(l["pressure"], layer.depth, l["depth"]).value_or(0.0);
    } else if (const Node design = root["design"]["pressure"]; design.present()) {
      // The design's pressure at this depth; its problems were reported once, there.
      std::vector<std::string> repeated;
      layer.pressure =
          read_pressure(Node(&design.json(), design.path(), repeated), layer.depth, l["depth"]).value_or(0.0);
    } else {
      l["pressure"].problem(R"(required ("design" gives no pressure))");
    }
    // The layer as a merge patch of the project file: its run records it.
    nlohmann::json patch = {{"name", project.name + ": " + layer.name}, {"layers", nullptr}};
    patch["design"]["depth"] = layer.depth;
    for (const char* key : {"soil", "pressure", "strength"})
      if (l[key].present()) (std::string(key) == "soil" ? patch["soil"] : patch["design"][key]) = l[key].json();
    layer.patch = patch.dump();
    layers.push_back(std::move(layer));
  }
  return layers;
}

}  // namespace frostwall::project::detail
