#include "freezing/plant_run.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "freezing/heat_run.hpp"
#include "freezing/plant_results.hpp"
#include "io/summary_file.hpp"

namespace frostwall::freezing {

namespace {

design::Brine as_design(const project::BrineProperties& b) {
  return {b.density, b.viscosity, b.conductivity, b.heat_capacity};
}

}  // namespace

CircuitSettings circuit_settings(const project::Project& p) {
  const auto& section = std::get<project::ShaftSection>(p.geometry);
  const auto& plant = *p.plant;
  CircuitSettings s;
  s.pipe = {section.pipe.diameter,     plant.pipe.wall_thickness,       plant.pipe.wall_conductivity,
            plant.pipe.inner_diameter, plant.pipe.inner_wall_thickness, plant.pipe.inner_wall_conductivity,
            plant.pipe.length};
  s.brine_at = [brine = plant.brine](double T) { return as_design(brine.at(T)); };
  s.brine = s.brine_at(plant.supply.at(0.0));
  s.flow = plant.flow_per_pipe;
  s.channel = plant.channel == project::SupplyChannel::annulus ? design::SupplyChannel::annulus
                                                               : design::SupplyChannel::inner;
  s.supply = plant.supply;
  s.capacity = plant.capacity;
  s.min_supply = plant.min_supply_temperature;
  s.pipes = project::pipe_count(section.layout) - static_cast<int>(section.layout.failed_pipes.size());
  s.interval = plant.exchange_interval;
  s.longest_interval = plant.longest_exchange_interval;
  s.profile_times = p.time.snapshots;
  return s;
}

PlantOutcome run_plant(const project::Project& p, const std::vector<PlantSection>& sections,
                       const project::RunOptions& options, const std::filesystem::path& out) {
  std::vector<CircuitSection> circuit;
  for (const auto& s : sections) {
    check_run_inputs(s.section.project);
    circuit.push_back(s.section);
  }
  const auto settings = circuit_settings(p);
  auto run = run_brine_circuit(circuit, settings, options);
  std::vector<std::string> names;
  for (const auto& s : sections) names.push_back(s.name);
  write_plant_csv(out / "plant.csv", names, run);
  PlantOutcome outcome;
  outcome.plant = plant_summary(p, settings, sections, run);
  outcome.sections = std::move(run.sections);
  return outcome;
}

CircuitSection mid_pipe_section(const project::Project& p, const std::string& project_text, RunExtension* extension) {
  return {p, 0.5 * p.plant->pipe.length, project_text, extension};
}

summary::Summary run_single_plant(const project::Project& p, const project::RunOptions& options) {
  const auto section = mid_pipe_section(p, options.project_text);
  const auto outcome = run_plant(p, {{fmt::format("{:g} m", section.depth), section}}, options, p.output.directory);
  auto j = summary::to_json(outcome.sections.front());
  j[summary::keys::plant] = outcome.plant;
  auto s = summary::from_json(j);
  io::write_summary(p.output.directory, s);
  return s;
}

}  // namespace frostwall::freezing
