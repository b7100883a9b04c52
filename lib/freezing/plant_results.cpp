#include "freezing/plant_results.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "freezing/plant_run.hpp"
#include "io/atomic_file.hpp"
#include "project/units.hpp"

namespace frostwall::freezing {

namespace {

using nlohmann::json;
using nlohmann::ordered_json;
constexpr double day = project::seconds_per_day;
constexpr double kwh = 3.6e6;  // J

ordered_json film_json(const design::ChannelFilm& f) {
  return {{"reynolds", f.reynolds}, {"prandtl", f.prandtl}, {"nusselt", f.nusselt}, {"h", f.h}};
}

// The brine along the pipe at a stop, every `stride`-th face.
ordered_json profile_json(const PlantProfile& at, design::SupplyChannel channel) {
  const auto& b = at.brine;
  const std::size_t faces = b.depth.size(), stride = std::max<std::size_t>(1, (faces - 1) / 50);
  ordered_json depth = json::array(), annulus = json::array(), inner = json::array(), draw = json::array();
  const auto& a = b.annulus(channel);
  const auto& i = channel == design::SupplyChannel::annulus ? b.up : b.down;
  for (std::size_t f = 0; f < faces; f += stride) {
    depth.push_back(b.depth[f]);
    annulus.push_back(a[f]);
    inner.push_back(i[f]);
    // The draw of the cell below the face (above it at the foot).
    draw.push_back(b.draw[std::min(f, b.draw.size() - 1)]);
  }
  return {{"day", at.time / day},
          {"supply_temperature", b.supply},
          {"return_temperature", b.return_temperature},
          {"depth", depth},
          {"annulus", annulus},
          {"inner", inner},
          {"draw_W_per_m", draw}};
}

// The sizing figures: the peak load over the run and over the active phase
// (up to the last section's closure), the load at the end, the energy.
ordered_json sizing(const std::vector<PlantRow>& rows, const std::vector<std::optional<double>>& closure,
                    std::optional<double> cop) {
  // The active phase ends when the last section closes (never: the whole run).
  double latest = 0.0;
  bool all_closed = true;
  for (const auto& c : closure) all_closed = all_closed && c, latest = c ? std::max(latest, *c) : latest;

  double peak = -std::numeric_limits<double>::infinity(), peak_day = 0.0, energy = 0.0, before = 0.0;
  double active_energy = 0.0, active_time = 0.0;
  for (const auto& r : rows) {
    if (r.load > peak) peak = r.load, peak_day = r.time / day;
    energy += r.load * (r.time - before);
    if (!all_closed || r.time <= latest * day) active_energy += r.load * (r.time - before), active_time = r.time;
    before = r.time;
  }
  const auto& last = rows.back();
  ordered_json j = {{"peak_load_kw", peak / 1e3},
                    {"peak_load_day", peak_day},
                    {"active_phase_end_day", all_closed ? json(latest) : json()},
                    {"active_mean_load_kw", active_time > 0.0 ? json(active_energy / active_time / 1e3) : json()},
                    {"end_load_kw", last.load / 1e3},
                    {"end_supply_temperature", last.supply},
                    {"end_return_temperature", last.return_temperature},
                    {"end_difference_K", last.return_temperature - last.supply},
                    {"energy_kwh", energy / kwh},
                    {"electricity_kwh", cop ? json(energy / kwh / *cop) : json()}};
  return j;
}

}  // namespace

void write_plant_csv(const std::filesystem::path& file, const std::vector<std::string>& names, const CircuitRun& run) {
  std::string csv = "day,load_kW,supply_C,return_C,film_W_per_m2K";
  for (const auto& n : names) csv += fmt::format(",brine_C {}", n);
  for (const auto& n : names) csv += fmt::format(",draw_W_per_m {}", n);
  csv += "\n";
  for (const auto& r : run.series) {
    csv += fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}", r.time / day, r.load / 1e3, r.supply, r.return_temperature,
                       r.film);
    for (double b : r.brine) csv += fmt::format(",{:.6g}", b);
    for (double q : r.draw) csv += fmt::format(",{:.6g}", q);
    csv += "\n";
  }
  io::write_text_file(file, csv);
}

ordered_json plant_summary(const project::Project& p, const CircuitSettings& s,
                           const std::vector<PlantSection>& sections, const CircuitRun& run) {
  const auto& plant = *p.plant;
  std::vector<std::optional<double>> closure;
  for (const auto& summary : run.sections) closure.push_back(summary.closure_time_days);
  ordered_json j = {
      {"pipes", s.pipes},
      {"flow_per_pipe_m3_h", s.flow * 3600.0},
      {"supply_channel", s.channel == design::SupplyChannel::annulus ? "annulus" : "inner"},
      {"capacity_kw", plant.capacity ? json(*plant.capacity / 1e3) : json()},
      {"min_supply_temperature", plant.capacity ? json(plant.min_supply_temperature) : json()},
      {"cop", summary::number_or_null(plant.cop)},
      {"brine",
       {{"mass_fraction", plant.brine.mass_fraction},
        {"freezing_point", plant.brine.freezing_point()},
        {"density", run.brine.density},
        {"viscosity", run.brine.viscosity},
        {"conductivity", run.brine.conductivity},
        {"heat_capacity", run.brine.heat_capacity}}},
      {"films",
       {{"annulus", film_json(run.resistances.annulus)},
        {"inner", film_json(run.resistances.inner)},
        {"R_channels", run.resistances.channels},
        {"R_ground", run.resistances.ground}}},
  };
  j.update(sizing(run.series, closure, plant.cop));
  j["heat_balance"] = {{"plant_J", run.plant_heat}, {"ground_J", run.ground_heat}};
  ordered_json entries = json::array();
  for (std::size_t k = 0; k < sections.size(); ++k)
    entries.push_back({{"name", sections[k].name},
                       {"depth", sections[k].section.depth},
                       {"weight_m", run.weights[k]},
                       {"brine_temperature", run.series.back().brine[k]},
                       {"draw_W_per_m", run.series.back().draw[k]},
                       {"closure_time_days", summary::number_or_null(closure[k])}});
  j["sections"] = entries;
  // The series thinned to at most about 240 rows (plant.csv has every one).
  const std::size_t stride = std::max<std::size_t>(1, (run.series.size() + 239) / 240);
  ordered_json series = json::array();
  for (std::size_t k = 0; k < run.series.size(); ++k) {
    if (k % stride != 0 && k + 1 != run.series.size()) continue;
    const auto& r = run.series[k];
    series.push_back({{"day", r.time / day},
                      {"load_kw", r.load / 1e3},
                      {"supply_temperature", r.supply},
                      {"return_temperature", r.return_temperature},
                      {"brine_temperature", r.brine}});
  }
  j["series"] = series;
  ordered_json profiles = json::array();
  for (const auto& at : run.profiles) profiles.push_back(profile_json(at, s.channel));
  j["profiles"] = profiles;
  return j;
}

}  // namespace frostwall::freezing
