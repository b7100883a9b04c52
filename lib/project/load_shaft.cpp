// The freeze pipe and the layers of a shaft section (load_shaft.hpp).
#include "project/load_shaft.hpp"

#include <fmt/format.h>
#include <set>

#include "project/load_reports.hpp"

namespace frostwall::project::detail {

Pipe read_pipe(const Node& n) {
  Pipe pipe;
  if (!n.object({"diameter", "temperature", "model", "boundary", "brine_temperature", "heat_transfer_coefficient"}))
    return pipe;
  pipe.diameter = n["diameter"].required().positive().value_or(0.0);
  pipe.model = n["model"].choice<PipeModel>("pipe model", {{"disc", PipeModel::disc}, {"point", PipeModel::point}})
                   .value_or(PipeModel::disc);
  pipe.boundary = n["boundary"].choice<PipeBoundary>("pipe boundary", {{"fixed", PipeBoundary::fixed}, {"brine", PipeBoundary::brine}})
                      .value_or(PipeBoundary::fixed);
  if (pipe.boundary == PipeBoundary::fixed) {
    pipe.temperature = read_schedule(n["temperature"].required());
    for (const char* key : {"brine_temperature", "heat_transfer_coefficient"})
      if (n[key].present()) n[key].problem(R"(only used with "boundary": "brine")");
    return pipe;
  }
  // Brine: the schedule is the brine's; the wall's temperature follows from
  // the heat the ground gives up through the film.
  if (n["temperature"].present())
    n["temperature"].problem(R"(with "boundary": "brine" the pipe wall's temperature is computed; give "brine_temperature")");
  pipe.temperature = read_schedule(n["brine_temperature"].required());
  pipe.heat_transfer_coefficient = n["heat_transfer_coefficient"].required().positive().value_or(0.0);
  if (pipe.model == PipeModel::point)
    n["boundary"].problem(R"("brine" needs "model": "disc" (a film needs the pipe's wall))");
  return pipe;
}

void warn_warm_pipe(const Node& n, const Pipe& pipe, double freezing_point, std::vector<std::string>& warnings) {
  const Node temperature = n[pipe.boundary == PipeBoundary::brine ? "brine_temperature" : "temperature"];
  if (!temperature.present()) return;
  const bool is_schedule = temperature.json().is_array();
  const char* what = pipe.boundary == PipeBoundary::brine ? "brine" : "pipe";
  for (std::size_t i = 0; i < pipe.temperature.points.size(); ++i)
    if (const double t = pipe.temperature.points[i].second; t > freezing_point)
      warnings.push_back(fmt::format("{}: {} degC is above the soil's freezing point ({} degC); "
                                     "a {} this warm cannot freeze the ground",
                                     is_schedule ? temperature[i].path() : temperature.path(), t, freezing_point, what));
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
    if (depth && *depth < 0.0) l["depth"].problem(fmt::format("must not be negative (metres below the surface), got {}", *depth));
    layer.depth = depth.value_or(0.0);
    layer.soil = l["soil"].present() ? read_soil(l["soil"], ignored) : project.soil;
    layer.strength = l["strength"].present() ? read_strength(l["strength"]) : project.design.strength;
    if (l["pressure"].present()) {
      layer.pressure = read_pressure(l["pressure"], layer.depth, l["depth"]).value_or(0.0);
    } else if (const Node design = root["design"]["pressure"]; design.present()) {
      // The design's pressure at this depth; its problems were reported once, there.
      std::vector<std::string> repeated;
      layer.pressure = read_pressure(Node(&design.json(), design.path(), repeated), layer.depth, l["depth"]).value_or(0.0);
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
