// The freezing plant's section: the sizing table (peak load over the run
// and while the wall forms, the load and the supply and return at the end,
// energy and electricity), the plant's load and its supply and return over
// time with each section's brine, and the brine along the pipe and the heat
// it draws against depth at the snapshots; a headline card with the peak.
#include <fmt/core.h>

#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

std::vector<double> column(const json& rows, const char* key) {
  std::vector<double> v;
  for (const auto& r : rows) v.push_back(r.value(key, std::nan("")));
  return v;
}

json sizing_rows(const json& plant) {
  json rows = json::array();
  const auto kw = [](const json& v) { return v.is_number() ? number(v, 1) + " kW" : std::string("–"); };
  rows.push_back(
      row("Peak load", fmt::format("{} on day {}", kw(plant["peak_load_kw"]), number(plant["peak_load_day"], 1))));
  if (plant["capacity_kw"].is_number())
    rows.push_back(row("Capacity", fmt::format("{}, supply no colder than {} °C", kw(plant["capacity_kw"]),
                                               number(plant["min_supply_temperature"], 1))));
  const json end = plant["active_phase_end_day"];
  rows.push_back(row(
      "Mean load while the wall forms",
      end.is_number()
          ? fmt::format("{} (to day {}, the last section's closure)", kw(plant["active_mean_load_kw"]), number(end, 1))
          : fmt::format("{} (a section never closed: the whole run)", kw(plant["active_mean_load_kw"]))));
  rows.push_back(row("Load at the end", kw(plant["end_load_kw"])));
  rows.push_back(row("Supply and return at the end",
                     fmt::format("{} / {} °C ({} K apart)", number(plant["end_supply_temperature"], 2),
                                 number(plant["end_return_temperature"], 2), number(plant["end_difference_K"], 2))));
  rows.push_back(row("Heat drawn over the run", number(plant["energy_kwh"], 0) + " kWh"));
  if (plant["electricity_kwh"].is_number())
    rows.push_back(row("Electricity", fmt::format("{} kWh at a COP of {}", number(plant["electricity_kwh"], 0),
                                                  number(plant["cop"], 2))));
  return rows;
}

}  // namespace

void add_plant(const RunRecord& run, json& view) {
  view["has_plant"] = false;
  view["plant_card"] = false;
  if (!run.summary.contains(keys::plant)) return;
  const json& p = run.summary[keys::plant];
  view["has_plant"] = true;
  const json& b = p["brine"];
  const json& f = p["films"];
  view["plant_note"] = fmt::format(
      "{} pipes with flow, {} m³/h each down the {}; calcium chloride brine at {} % by mass (freezes at {} °C; "
      "at the end {} kg/m³, {} mPa s); annulus film Re {}, h {} W/(m² K); resistances {} (between the channels) "
      "and {} m K/W (annulus to ground). The sections draw from one circuit: a section's brine is the annulus' "
      "temperature at its depth.",
      p.value("pipes", 0), number(p["flow_per_pipe_m3_h"], 2), p.value("supply_channel", ""),
      number(100.0 * b.value("mass_fraction", 0.0), 1), number(b["freezing_point"], 1), number(b["density"], 0),
      number(1e3 * b.value("viscosity", 0.0), 2), number(f["annulus"]["reynolds"], 0), number(f["annulus"]["h"], 0),
      number(f["R_channels"], 3), number(f["R_ground"], 4));
  view["plant_sizing"] = sizing_rows(p);
  view["plant_card"] = true;
  view["plant_peak"] = number(p["peak_load_kw"], 1) + " kW";
  view["plant_peak_note"] = fmt::format("{} kW at the end; supply {} °C, return {} °C", number(p["end_load_kw"], 1),
                                        number(p["end_supply_temperature"], 1), number(p["end_return_temperature"], 1));
  json sections = json::array();
  for (const auto& s : p.value("sections", json::array()))
    sections.push_back({{"name", s.value("name", "")},
                        {"depth", number(s["depth"], 1)},
                        {"brine", number(s["brine_temperature"], 2)},
                        {"draw", number(s["draw_W_per_m"], 1)},
                        {"closure", number(s["closure_time_days"], 2)}});
  view["plant_sections"] = sections;

  const json& rows = p["series"];
  const auto day = column(rows, "day");
  Chart load = line_chart("The plant's load", "time (d)", "load (kW)", {line("load", day, column(rows, "load_kw"))});
  if (p["capacity_kw"].is_number()) load.guides.push_back({false, p["capacity_kw"].get<double>(), "capacity"});
  load.y_include = {0.0};
  std::vector<Series> temperatures{line("supply", day, column(rows, "supply_temperature")),
                                   line("return", day, column(rows, "return_temperature"))};
  for (std::size_t k = 0; k < sections.size(); ++k) {
    Series s = line("brine at " + sections[k]["name"].get<std::string>(), day, {}, "", true);
    for (const auto& r : rows) s.y.push_back(r["brine_temperature"][k].get<double>());
    temperatures.push_back(std::move(s));
  }
  Chart brine = line_chart("Supply, return and each section's brine", "time (d)", "temperature (°C)", temperatures);
  std::vector<Series> along, draw;
  const auto& profiles = p.value("profiles", json::array());
  const auto colours = sequential_colours(profiles.size());
  for (std::size_t k = 0; k < profiles.size(); ++k) {
    const auto& at = profiles[k];
    const auto depth = at["depth"].get<std::vector<double>>();
    const std::string label = "day " + number(at["day"], 1);
    along.push_back(line(label, depth, at["annulus"].get<std::vector<double>>(), colours[k]));
    along.push_back(line("", depth, at["inner"].get<std::vector<double>>(), colours[k], true));
    draw.push_back(line(label, depth, at["draw_W_per_m"].get<std::vector<double>>(), colours[k]));
  }
  Chart depth_T = line_chart("The brine along the pipe", "depth (m)", "temperature (°C)", along);
  Chart depth_q = line_chart("The heat drawn along the pipe", "depth (m)", "heat drawn (W per m of pipe)", draw);
  depth_q.y_include = {0.0};
  view["plant_charts"] = json::array(
      {{{"svg", render_svg(load)},
        {"caption", "The heat all pipes draw from the ground, averaged over each exchange of the brine."}},
       {{"svg", render_svg(brine)},
        {"caption", "The brine leaving the plant and coming back, and the brine each section sees (dashed)."}},
       {{"svg", render_svg(depth_T)},
        {"caption", "The brine down the annulus (solid) and in the inner pipe (dashed) at the snapshots."}},
       {{"svg", render_svg(depth_q)},
        {"caption", "Heat drawn per metre of pipe, interpolated between the sections' depths."}}});
}

}  // namespace frostwall::report::detail
