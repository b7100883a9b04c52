#include "report/report.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "io/summary_file.hpp"
#include "report/mustache_view.hpp"
#include "report/nice_scale.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"
#include "report/templates.hpp"

namespace frostwall::report {

namespace fs = std::filesystem;
using nlohmann::json;

namespace detail {

std::string metres(double v, int decimals) {
  return !std::isfinite(v) || v == 0.0 || std::abs(v) >= 1e-3 ? number(v, decimals) : fmt::format("{:.4g}", v);
}

double smoothing_length(const json& run_facts) {
  const auto h = run_facts.find(keys::smoothing_length);
  if (h == run_facts.end() || !h->is_number() || h->get<double>() <= 0.0)
    throw std::runtime_error("summary.json: run.smoothing_length is missing; it is needed to draw the maps");
  return h->get<double>();
}

std::string with_error(const json& value, const json& error, int decimals) {
  if (!value.is_number() || !error.is_number()) return number(value, decimals);
  return report::with_error(value.get<double>(), error.get<double>(), decimals);
}

json row(const std::string& label, const std::string& value) { return {{"label", label}, {"value", value}}; }

Series line(std::string label, std::vector<double> x, std::vector<double> y, std::string colour, bool dashed) {
  Series s;
  s.label = std::move(label), s.x = std::move(x), s.y = std::move(y), s.colour = std::move(colour);
  s.dashed = dashed;
  return s;
}

namespace {

std::string extent(const json& stretch) {
  if (!stretch.is_object() || !stretch[keys::inner].is_number()) return "–";
  return number(stretch[keys::inner], 2) + " – " + number(stretch[keys::outer], 2);
}

}  // namespace

void add_headline(const RunRecord& run, json& view) {
  const auto& s = run.summary;
  view["shaft"] = run.shaft();
  view["plain"] = !run.shaft();
  view["cards"] = json::array();
  view["has_cards"] = false;
  view["snapshots"] = json::array();
  for (const char* key : {"closure_value", "closure_note", "contact_value", "contact_note", "last_day",
                          "last_min_thickness", "last_mean_temperature", "design_value", "design_note", "design_class"})
    view[key] = "";
  if (!run.shaft()) {
    add_plain_headline(run, view);
    return;
  }
  const auto& closure = s.value(keys::closure_time_days, json());
  const auto& wall = s[keys::wall];
  const std::string end_day = wall.empty() ? "the end" : number(wall.back()[keys::day], 0);
  view["closure_value"] =
      closure.is_number() ? "day " + with_error(closure, s.value(keys::error_of(keys::closure_time_days), json()), 1)
                          : "not closed";
  view["closure_note"] = closure.is_number() ? "a fully frozen ring cuts the shaft off from the far field"
                                             : "not within the run (to day " + end_day + ")";
  // Older summaries have no front_contact_days: the card then says so.
  const auto& contact = s.value(keys::front_contact_days, json());
  view["contact_value"] =
      contact.is_number() ? "day " + with_error(contact, s.value(keys::error_of(keys::front_contact_days), json()), 1)
                          : (s.contains(keys::front_contact_days) ? "not yet" : "–");
  view["contact_note"] = contact.is_number() ? "half-frozen columns touch; not yet a closed wall"
                                             : "the columns have not touched within the run";
  json rows = json::array();
  for (const auto& w : wall)
    rows.push_back(
        {{"day", fmt::format("{:g}", w[keys::day].get<double>())},
         {"min_thickness", with_error(w[keys::min_thickness], w.value(keys::error_of(keys::min_thickness), json()), 2)},
         {"OA_thickness",
          with_error(w[keys::OA][keys::thickness], w[keys::OA].value(keys::error_of(keys::thickness), json()), 2)},
         {"OA_extent", extent(w[keys::OA])},
         {"OB_thickness",
          with_error(w[keys::OB][keys::thickness], w[keys::OB].value(keys::error_of(keys::thickness), json()), 2)},
         {"OB_extent", extent(w[keys::OB])},
         {"mean_temperature",
          with_error(w[keys::mean_temperature_OB], w.value(keys::error_of(keys::mean_temperature_OB), json()), 2)}});
  view["snapshots"] = rows;
  if (!wall.empty()) {
    view["last_day"] = fmt::format("{:g}", wall.back()[keys::day].get<double>());
    const auto& last = wall.back();
    view["last_min_thickness"] =
        with_error(last[keys::min_thickness], last.value(keys::error_of(keys::min_thickness), json()), 2) + " m";
    view["last_mean_temperature"] = last[keys::mean_temperature_OB].is_number()
                                        ? with_error(last[keys::mean_temperature_OB],
                                                     last.value(keys::error_of(keys::mean_temperature_OB), json()), 1) +
                                              " °C"
                                        : "–";
  }
  const auto& d = s.value(keys::design, json::object());
  const bool has_target = d.value(keys::required_thickness, json()).is_number() ||
                          d.value(keys::max_mean_temperature, json()).is_number();
  if (!has_target && d.contains(keys::met_day)) {  // the wall check from pressure and strength
    const bool met = d[keys::met_day].is_number();
    view["design_value"] = met ? "PASS" : "FAIL";
    view["design_class"] = met ? "pass" : "fail";
    view["design_note"] = design_verdict(s);
    return;
  }
  if (!has_target) {
    view["design_value"] = "no targets";
    view["design_note"] = "the project sets no design targets";
    return;
  }
  std::string targets;
  if (d[keys::required_thickness].is_number())
    targets = "thinnest wall ≥ " + number(d[keys::required_thickness], 2) + " m";
  if (d[keys::max_mean_temperature].is_number())
    targets += (targets.empty() ? "" : " and ") +
               ("mean T on OB ≤ " + number(d[keys::max_mean_temperature], 1) + " °C");
  const bool pass = d.value(keys::pass, false);
  view["design_value"] = pass ? "PASS" : "FAIL";
  view["design_class"] = pass ? "pass" : "fail";
  view["design_note"] =
      pass ? targets + ", met on day " +
                 with_error(d[keys::reached_day], d.value(keys::error_of(keys::reached_day), json()), 1)
           : targets + ": not met by day " + end_day;
}

void add_run_facts(const RunRecord& run, json& view) {
  const auto& r = run.summary.value(keys::run, json::object());
  json rows = json::array();
  auto fact = [&](const char* key, const std::string& label, auto&& format) {
    if (r.contains(key)) rows.push_back(row(label, format(r[key])));
  };
  auto integer = [](const json& v) { return v.is_number() ? fmt::format("{}", v.get<long long>()) : v.dump(); };
  auto text = [](const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); };
  fact(keys::particles, "free particles", integer);
  fact("boundary_particles", "fixed-temperature particles", integer);
  const bool pd = r.value("method", std::string()) == "pd";
  fact("pairs", pd ? "thermal bonds (pairs)" : "particle pairs", integer);
  fact(keys::steps, "time steps", integer);
  fact(keys::spacing, "particle spacing",
       [](const json& v) { return (v.is_number() ? metres(v.get<double>(), 4) : "–") + " m"; });
  if (!pd) {  // PD bonds have a horizon, no kernel
    fact(keys::smoothing_length, "smoothing length h", [](const json& v) { return number(v, 4) + " m"; });
    fact("kernel", "kernel", text);
  }
  fact(keys::integrator, "integrator", text);
  fact("threads", "threads", integer);
  fact(keys::wall_seconds, "wall time", [](const json& v) { return number(v, 1) + " s"; });
  rows.push_back(row("frostwall version", run.summary.value(keys::frostwall_version, "?")));
  if (run.summary.contains(keys::heat_balance)) {
    const auto& hb = run.summary[keys::heat_balance];
    double from = 0.0;
    for (const auto& [name, q] : hb["from_boundaries"].items()) from += q.get<double>();
    const double stored = hb.value("stored_change", 0.0);
    rows.push_back(row("heat balance", fmt::format("stored change {} MJ/m, from the boundaries {} MJ/m",
                                                   number(stored / 1e6, 2), number(from / 1e6, 2))));
  }
  if (const auto& e = run.summary.value(keys::error_estimate, json::object()); e.contains(keys::status)) {
    if (e[keys::status] == "done") {
      std::string spacings;
      for (const auto& h : e.value("spacings", json::array()))
        spacings += (spacings.empty() ? "" : ", ") + metres(h.get<double>(), 4);
      rows.push_back(
          row("error estimate", fmt::format("from three coarser runs (spacings {} m; {} s): the ± values are the "
                                            "discretisation's error only, not the soil data's or the model's",
                                            spacings, number(e.value("coarse_seconds", json()), 1))));
    } else {
      rows.push_back(row("error estimate", "none: " + e.value("reason", std::string())));
    }
  }
  view["run_rows"] = rows;

  // Links to the other files of the run, as they are in the directory.
  const std::vector<std::pair<std::string, std::string>> known{
      {"summary.json", "results in machine-readable form (closure, wall, design, sensors, run)"},
      {"project.json", "the project file as given"},
      {"wall.csv", "wall extents and OB temperature over time"},
      {"profiles_OA.csv", "temperature along OA at the snapshots"},
      {"profiles_OB.csv", "temperature along OB at the snapshots"},
      {"monitoring.csv", "sensor temperatures over time"},
      {"brine.csv", "brine pipes: pipe wall temperature and heat extracted per metre over time"},
      {"plant.csv", "the plant: load, supply and return, each section's brine and heat drawn at every exchange"},
      {"damage.csv", "broken bonds, largest damage and damaged area at every mechanical equilibrium"},
      {"field.pvd",
       run.shaft() ? "ParaView: the wedge's particles at every snapshot" : "ParaView: the particles at every snapshot"},
      {"ring.pvd", "ParaView: the whole ring at every snapshot"},
  };
  json files = json::array();
  for (const auto& [name, what] : known)
    if (fs::exists(run.dir / name)) files.push_back({{"name", name}, {"href", name}, {"description", what}});
  std::vector<std::string> series;
  for (const auto& entry : fs::directory_iterator(run.dir)) {
    const std::string name = entry.path().filename().string();
    if ((name.rfind("field_", 0) == 0 || name.rfind("ring_", 0) == 0) && entry.path().extension() == ".vtu")
      series.push_back(name);
    if (name.rfind("interface", 0) == 0 && entry.path().extension() == ".vtp") series.push_back(name);
  }
  std::sort(series.begin(), series.end());
  for (const auto& name : series) {
    const std::string what = name.rfind("field_", 0) == 0  ? "particles of the simulated region (VTK)"
                             : name.rfind("ring_", 0) == 0 ? "whole ring (VTK)"
                                                           : "frozen front curves (VTK polylines)";
    files.push_back({{"name", name}, {"href", name}, {"description", what}});
  }
  view["files"] = files;
}

}  // namespace detail

json report_view(const fs::path& dir) {
  detail::RunRecord run;
  run.dir = dir;
  if (!fs::exists(dir / "summary.json"))
    throw std::runtime_error(dir.string() + ": no summary.json (not a frostwall output directory?)");
  run.summary = summary::to_json(io::read_summary(dir));
  // A layered shaft: the maps, charts and files are the governing layer's.
  std::string layer_prefix;
  for (const auto& l : run.summary.value(keys::layers, json::array()))
    if (l["layer"].value("governing", false)) layer_prefix = l["layer"].value("directory", "") + "/";
  // A failed-pipe scenario beside the intact layout: the scenario's.
  if (run.summary.value(keys::scenario_directory, json()).is_string())
    layer_prefix = run.summary[keys::scenario_directory].get<std::string>() + "/";
  // An as-built shaft: the critical section's.
  for (const auto& s : run.summary.value(keys::sections, json::array()))
    if (s.value("critical", false)) layer_prefix = s.value("directory", "") + "/";
  if (!layer_prefix.empty()) run.dir = dir / layer_prefix;
  std::vector<std::string> warnings;
  for (const auto& w : run.summary.value(keys::warnings, json::array())) warnings.push_back(w.get<std::string>());
  if (const auto text = read_text(run.dir / "project.json")) {
    try {
      run.project = project::parse_project(*text, "project.json");
    } catch (const project::ProjectError& e) {
      warnings.push_back("project.json in the output directory does not load: " + e.problems().front());
    }
  }
  json view = json::object();
  view["version"] = run.summary.value(keys::frostwall_version, FROSTWALL_VERSION);
  view["title"] = run.summary.value(keys::project, "frostwall run");
  view["description"] = run.project && !run.project->description.empty() ? json(run.project->description) : json(false);
  view["css"] = std::string(templates::style_css);
  view["method_line"] = detail::method_line(run);
  json list = json::array();
  for (const auto& w : warnings) list.push_back({{"text", w}});
  view["warnings"] = list;
  view["has_warnings"] = !warnings.empty();
  view["cards"] = json::array();
  view["has_cards"] = false;
  if (run.summary.value(keys::physics, std::string()) == "cfd-dem") {
    detail::add_cfd_dem(run, view);
    return view;
  }
  view["cfd_dem"] = false;
  view["has_cfd_dem"] = false;
  detail::add_headline(run, view);
  detail::add_project(run, view);
  detail::add_maps(run, view);
  detail::add_groundwater(run, view);
  detail::add_plant(run, view);
  detail::add_excavation(run, view);
  detail::add_as_built(run, view);
  detail::add_calibration(run, view);
  detail::add_charts(run, view);
  detail::add_mechanics(run, view);
  detail::add_frost(run, view);
  detail::add_design(run, view);
  detail::add_run_facts(run, view);
  for (auto& f : view["files"]) f["href"] = layer_prefix + f["href"].get<std::string>();
  return view;
}

std::string render_report(const fs::path& dir) { return render_template(templates::report_html, report_view(dir)); }

fs::path write_report(const fs::path& dir) {
  const fs::path file = dir / "report.html";
  io::write_text_file(file, render_report(dir));
  return file;
}

}  // namespace frostwall::report
