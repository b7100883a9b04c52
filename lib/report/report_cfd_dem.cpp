// The report of a CFD-DEM run: the bed at the snapshots, minimum
// fluidisation when the run measured it, curves over time from series.csv
// and the pressure drop against the Darcy velocity, run facts and files.
#include <cmath>
#include <filesystem>
#include <fmt/format.h>

#include "report/report_sections.hpp"
#include "report/run_files.hpp"
#include "report/svg_chart.hpp"

namespace frostwall::report::detail {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json chart(const std::string& id, const Chart& c, const std::string& caption) {
  return {{"id", id}, {"title", c.title}, {"svg", render_svg(c)}, {"caption", caption}};
}

// One row per snapshot: the bed and the fluid's force on it.
json snapshot_rows(const json& s) {
  json snapshots = json::array();
  for (const auto& sn : s.value("snapshots", json::array())) {
    const auto& f = sn["mean_fluid_force_N"];
    snapshots.push_back(
        {{"time", number(sn["time"], 4)},
         {"grains", number(sn["grains_in_soil"], 0)},
         {"porosity", number(sn["porosity"], 4)},
         {"bed_length", number(sn["bed_length_m"].get<double>() * 1000.0, 2)},
         {"contacts", number(sn["contacts"], 0)},
         {"force", fmt::format("{:.3e}", std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>()))},
         {"pressure_drop", number(sn["pressure_drop_Pa"], 2)}});
  }
  return snapshots;
}

// Minimum fluidisation, when the run measured it (else no rows).
json fluidisation_rows(const json& s) {
  json fluid_rows = json::array();
  if (const auto it = s.find("minimum_fluidisation"); it != s.end()) {
    const json& f = *it;
    auto speed = [&](const char* key) {
      return f.contains(key) && f[key].is_number() ? number(f[key], 5) + " m/s" : std::string("not reached");
    };
    fluid_rows.push_back(row("minimum fluidisation velocity (pressure drop meets its plateau)", speed("velocity_m_s")));
    fluid_rows.push_back(row("Ergun's, for the bed as settled", speed("ergun_velocity_m_s")));
    fluid_rows.push_back(row("lift-off (bed 0.5 % longer)", speed("lift_velocity_m_s")));
    fluid_rows.push_back(
        row("plateau pressure drop / buoyant weight",
            number(f.value("plateau_pressure_drop_Pa", NAN), 2) + " / " + number(f["buoyant_weight_Pa"], 2) + " Pa"));
    fluid_rows.push_back(row("gradient at fluidisation / critical (G_s - 1)(1 - n)",
                             number(f.value("gradient", NAN), 3) + " / " + number(f["critical_gradient"], 3)));
    fluid_rows.push_back(
        row("bed as settled: porosity, length",
            number(f["porosity"], 4) + ", " + number(f["bed_length_m"].get<double>() * 1000.0, 2) + " mm"));
  }
  return fluid_rows;
}

// The curves over time from series.csv (none without the file).
json series_charts(const RunRecord& run) {
  const json& s = run.summary;
  json charts = json::array();
  if (!fs::exists(run.dir / "series.csv")) return charts;
  const CsvTable columns = read_csv(run.dir / "series.csv");
  auto column = [&](const std::string& name) {
    const auto* c = columns.column(name);
    return c ? *c : std::vector<double>{};
  };
  const auto t = column("time_s");
  if (!t.empty()) {
    Chart dp = line_chart("Pressure drop", "time (s)", "pressure drop (Pa)",
                          {line("inflow to outflow face", t, column("pressure_drop_Pa"))});
    if (const auto it = s.find("minimum_fluidisation"); it != s.end())
      dp.guides.push_back(Guide{false, (*it)["buoyant_weight_Pa"].get<double>(), "buoyant weight"});
    charts.push_back(
        chart("pressure_drop", dp, "The excess pressure at the inflow face less that at the outflow face."));
    if (s.contains("ergun")) {
      Series points = line("", column("inflow_velocity_m_s"), column("pressure_drop_Pa"));
      points.markers = true;
      Chart du = line_chart("Pressure drop against the Darcy velocity", "Darcy velocity (m/s)", "pressure drop (Pa)",
                            {points});
      du.guides = dp.guides;
      du.x_include = {0.0};
      du.y_include = {0.0};
      charts.push_back(
          chart("pressure_drop_velocity", du,
                "A fixed bed's pressure drop rises with the flow; a bed that fluidises holds its buoyant weight."));
    }
    Chart bed = line_chart("Bed porosity", "time (s)", "porosity", {line("", t, column("porosity"))});
    charts.push_back(chart("porosity", bed, "One less the grains' volume over the bed's (area times length)."));
    Chart contacts = line_chart("Contacts", "time (s)", "grain-grain contacts", {line("", t, column("contacts"))});
    charts.push_back(chart("contacts", contacts, "Contacts between grains (walls not counted)."));
    Chart force = line_chart(
        "Mean fluid force per grain along the bed axis", "time (s)", "force (N)",
        {line("drag", t, column("mean_drag_N")), line("pressure gradient", t, column("mean_pressure_gradient_force_N")),
         line("buoyancy", t, column("mean_buoyancy_N"))});
    charts.push_back(chart("fluid_force", force, "Signed along the bed axis, away from the face the grains rest on."));
    Chart settling = line_chart("Settling velocity", "time (s)", "mean velocity along gravity (m/s)",
                                {line("", t, column("settling_velocity_m_s"))});
    charts.push_back(chart("settling", settling, "The grains' volume-weighted mean velocity along gravity."));
  }
  return charts;
}

// The run's table: sizes, steps, time and where the packing came from.
json run_rows(const json& s) {
  json rows = json::array();
  rows.push_back(row("grains", fmt::format("{}", s.value("grains", 0L))));
  rows.push_back(row("MPI ranks", fmt::format("{}", s.value("ranks", 1))));
  rows.push_back(row("DEM time step", fmt::format("{:.3g} s", s.value("dem_timestep_s", NAN))));
  rows.push_back(row("fluid update", fmt::format("every {} DEM steps", s.value("coupling_interval", 0))));
  rows.push_back(row("DEM steps", fmt::format("{}", s.value("dem_steps", 0L))));
  rows.push_back(row("wall time", number(s.value("wall_time_s", NAN), 1) + " s"));
  rows.push_back(row("coupling share of the wall time", number(100.0 * s.value("coupling_share", NAN), 1) + " %"));
  if (s.contains("packing"))
    rows.push_back(row(
        "packing", s["packing"].value("read_from_cache", false) ? "read from the cache" : "placed and settled here"));
  rows.push_back(row("frostwall version", s.value(keys::frostwall_version, "?")));
  return rows;
}

// Links to the files of the run that are there, each with what it holds.
json run_file_links(const fs::path& dir) {
  const std::vector<std::pair<std::string, std::string>> known{
      {"summary.json", "results in machine-readable form"},
      {"series.csv", "the bed and the flow over time"},
      {"soil.csv", "the ground over the cavity over time: losses, zone porosity, point A, settlement, collapse zone"},
      {"project.json", "the project file as given"},
      {"grains.pvd", "ParaView: the grains at every snapshot (velocity, fluid force, contacts)"},
      {"fluid.pvd", "ParaView: the fluid grid at every snapshot (porosity, pressure, Darcy velocity)"},
      {"dem_commands.txt", "the LAMMPS commands this run sent, to replay with LAMMPS"},
      {"lammps.log", "LAMMPS's own log"}};
  json files = json::array();
  for (const auto& [name, what] : known)
    if (fs::exists(dir / name)) files.push_back({{"name", name}, {"href", name}, {"description", what}});
  return files;
}

}  // namespace

Chart line_chart(const std::string& title, const std::string& x_label, const std::string& y_label,
                 std::vector<Series> series) {
  Chart c;
  c.title = title;
  c.x_label = x_label;
  c.y_label = y_label;
  c.series = std::move(series);
  return c;
}

void add_cfd_dem(const RunRecord& run, json& view) {
  const json& s = run.summary;
  view["cfd_dem"] = true;
  view["has_cfd_dem"] = true;
  view["cfd_dem_note"] = fmt::format(
      "{} grains, {} fluid cells; fluid forces: {}. The bed is measured along {} from the face it rests on; "
      "the pressure is the excess over hydrostatic.",
      s.value("grains", 0L), s.contains("fluid_cells") ? s["fluid_cells"].dump() : "?",
      s.contains("fluid_forces") ? s["fluid_forces"].dump() : "?", s.value("bed_axis", std::string("z")));
  view["cfd_dem_snapshots"] = snapshot_rows(s);
  const json fluid_rows = fluidisation_rows(s);
  view["has_fluidisation"] = !fluid_rows.empty();
  view["fluidisation_rows"] = fluid_rows;
  view["charts"] = series_charts(run);
  view["run_rows"] = run_rows(s);
  view["files"] = run_file_links(run.dir);
  add_erosion(run, view);
}

}  // namespace frostwall::report::detail
