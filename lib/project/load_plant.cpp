#include "project/load_plant.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "project/load_basics.hpp"
#include "project/units.hpp"

namespace frostwall::project::detail {

namespace {

CoaxialGeometry read_coaxial(const Node& pipe, double diameter) {
  CoaxialGeometry g;
  g.inner_diameter = pipe["inner_diameter"].required().positive().value_or(0.0);
  g.wall_thickness = pipe["wall_thickness"].required().positive().value_or(0.0);
  g.wall_conductivity = pipe["wall_conductivity"].present() ? pipe["wall_conductivity"].positive().value_or(0.0) : 50.0;
  g.inner_wall_thickness = pipe["inner_wall_thickness"].required().positive().value_or(0.0);
  g.inner_wall_conductivity =
      pipe["inner_wall_conductivity"].present() ? pipe["inner_wall_conductivity"].positive().value_or(0.0) : 0.4;
  g.length = pipe["length"].required().positive().value_or(0.0);
  const double bore = diameter - 2.0 * g.wall_thickness;  // the annulus' outer wall
  if (diameter > 0.0 && g.wall_thickness > 0.0 && bore <= 0.0)
    pipe["wall_thickness"].problem(
        fmt::format("must be below half the pipe's diameter {}, got {}", diameter, g.wall_thickness));
  else if (bore > 0.0 && g.inner_diameter >= bore)
    pipe["inner_diameter"].problem(
        fmt::format("must be below the freeze pipe's bore {:g} (diameter less twice wall_thickness), got {}", bore,
                    g.inner_diameter));
  if (g.inner_diameter > 0.0 && g.inner_wall_thickness >= g.inner_diameter / 2.0)
    pipe["inner_wall_thickness"].problem(fmt::format("must be below half the inner pipe's diameter {}, got {}",
                                                     g.inner_diameter, g.inner_wall_thickness));
  return g;
}

void read_brine(const Node& n, Plant& plant) {
  if (!n.object({"flow_per_pipe", "supply", "concentration", "density", "viscosity", "conductivity", "heat_capacity"}))
    return;
  plant.flow_per_pipe = n["flow_per_pipe"].required().positive().value_or(0.0) / 3600.0;
  plant.channel = n["supply"]
                      .choice<SupplyChannel>("supply channel",
                                             {{"annulus", SupplyChannel::annulus}, {"inner", SupplyChannel::inner}})
                      .value_or(SupplyChannel::annulus);
  auto& b = plant.brine;
  if (const Node x = n["concentration"]; x.present()) {
    const auto fraction = x.positive();
    if (fraction && *fraction > 0.30)
      x.problem(fmt::format("must be at most 0.30 (a mass fraction; the built-in brine's range), got {}", *fraction));
    else if (fraction) b.mass_fraction = *fraction;
  }
  if (n["density"].present()) b.density = n["density"].positive();
  if (n["viscosity"].present()) b.viscosity = n["viscosity"].positive();
  if (n["conductivity"].present()) b.conductivity = n["conductivity"].positive();
  if (n["heat_capacity"].present()) b.heat_capacity = n["heat_capacity"].positive();
}

void read_supply(const Node& n, Plant& plant) {
  const Node supply = n["supply_temperature"], capacity = n["capacity_kw"], coldest = n["min_supply_temperature"];
  if (supply.present() == capacity.present()) {
    supply.problem(R"(give either "supply_temperature" or "capacity_kw" (with "min_supply_temperature"))");
    return;
  }
  if (supply.present()) {
    plant.supply = read_schedule(supply);
    if (coldest.present()) coldest.problem(R"(only used with "capacity_kw")");
    return;
  }
  plant.capacity = capacity.positive().value_or(1.0) * 1e3;
  plant.min_supply_temperature = coldest.required().number().value_or(0.0);
  plant.supply = TemperatureSchedule::fixed(plant.min_supply_temperature);
}

// The brine must stay liquid at the plant's coldest supply.
void check_brine_liquid(const Node& n, const Plant& plant) {
  const double freezing = plant.brine.freezing_point();
  const Node given = plant.capacity ? n["min_supply_temperature"] : n["supply_temperature"];
  for (std::size_t i = 0; i < plant.supply.points.size(); ++i)
    if (const double T = plant.supply.points[i].second; T <= freezing)
      (given.json().is_array() ? given[i] : given)
          .problem(fmt::format("{} degC freezes the brine (calcium chloride at mass fraction {} freezes at {:.1f} "
                               "degC; raise brine.concentration or the supply)",
                               T, plant.brine.mass_fraction, freezing));
}

}  // namespace

std::optional<Plant> read_plant(const Node& root, const Project& project) {
  const Node n = root["plant"], pipe = root["pipe"], brine = root["brine"];
  const auto* section = std::get_if<ShaftSection>(&project.geometry);
  if (!n.present()) {
    if (brine.present()) brine.problem(R"(only used with "plant" (the brine circuit))");
    for (const char* key : coaxial_keys)
      if (pipe[key].present()) pipe[key].problem(R"(only used with "plant" (the coaxial freeze pipe))");
    return std::nullopt;
  }
  if (!section) {
    n.problem(R"(only used with "layout" (shaft sections))");
    return std::nullopt;
  }
  if (!n.object({"supply_temperature", "capacity_kw", "min_supply_temperature", "cop", "exchange_hours",
                 "longest_exchange_hours"}))
    return std::nullopt;
  Plant plant;
  read_supply(n, plant);
  if (n["cop"].present()) plant.cop = n["cop"].positive();
  const auto hours = [&](const char* key, double otherwise) {
    return n[key].present() ? n[key].positive().value_or(otherwise) * 3600.0 : otherwise * 3600.0;
  };
  plant.exchange_interval = hours("exchange_hours", 1.0);
  plant.longest_exchange_interval = hours("longest_exchange_hours", std::max(12.0, plant.exchange_interval / 3600.0));
  if (plant.longest_exchange_interval < plant.exchange_interval)
    n["longest_exchange_hours"].problem(fmt::format("must be at least exchange_hours ({} h), got {}",
                                                    plant.exchange_interval / 3600.0,
                                                    plant.longest_exchange_interval / 3600.0));
  read_brine(brine.required(), plant);
  if (pipe.present()) plant.pipe = read_coaxial(pipe, section->pipe.diameter);
  check_brine_liquid(n, plant);
  if (section->pipe.model == PipeModel::point)
    pipe["model"].problem(R"("plant" needs "model": "line" or "disc" (the brine's film needs the pipe's wall))");
  if (project.compare_intact) root["compare_intact"].problem(R"(not used with "plant")");
  const double length = plant.pipe.length;
  for (std::size_t k = 0; k < project.layers.size(); ++k)
    if (length > 0.0 && project.layers[k].depth > length)
      root["layers"][k]["depth"].problem(fmt::format("must be within the freeze pipe's length {} (pipe.length), got {}",
                                                     length, project.layers[k].depth));
  return plant;
}

}  // namespace frostwall::project::detail
