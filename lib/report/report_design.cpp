// The wall check's section of the report: the verdict in words,
// every formula's thickness on the last snapshot with its validity, required
// against achieved thickness over time (per layer for a layered shaft), the
// table by layer, and the brine pipes' wall temperature and heat.
#include <cmath>
#include <fmt/core.h>
#include <string_view>

#include "report/report_sections.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

struct FormulaText {
  const char* key;
  const char* label;
  const char* valid_when;
};
constexpr FormulaText formulas[] = {
    {"lame_tresca", "Lamé, elastic, Tresca", "s > 2P"},
    {"lame_mises", "Lamé, elastic, von Mises", "s > √3 P"},
    {"domke", "Domke", "always"},
    {"plastic_tresca", "plastic limit, Tresca", "always"},
    {"plastic_mohr_coulomb", "plastic limit, Mohr-Coulomb", "with a friction angle"},
};

std::string formula_label(const std::string& key) {
  for (const auto& f : formulas)
    if (key == f.key) return f.label;
  return key;
}

// The wall the check measured: on the isotherm when there is one.
json achieved(const json& w) {
  return w.contains(keys::isotherm_thickness) ? w[keys::isotherm_thickness] : w[keys::min_thickness];
}

// "design met on day 47 in clay at 200 m; utilisation 0.93 on day 120"
std::string verdict(const json& summary, const std::string& where) {
  const json d = summary.value(keys::design, json::object());
  const json wall = summary.value(keys::wall, json::array());
  const std::string last_day = wall.empty() ? "the end" : number(wall.back()[keys::day], 0);
  const std::string u = wall.empty() ? "–"
                                     : with_error(wall.back().value(keys::utilisation, json()),
                                                  wall.back().value(keys::error_of(keys::utilisation), json()), 2);
  // A wall that passes and later fails again (a pipe lost, a warm spell of brine) says so.
  const std::string again = d.value("stays_met", true) ? "" : " (but not for good: it fails again later)";
  const std::string met =
      d.value(keys::met_day, json()).is_number()
          ? fmt::format("design met on day {}{}{}",
                        with_error(d[keys::met_day], d.value(keys::error_of(keys::met_day), json()), 0), where, again)
          : fmt::format("design not met by day {}{}", last_day, where);
  return fmt::format("{}; utilisation {} on day {}", met, u, last_day);
}

std::string layer_place(const json& layer) {
  return layer.is_object() ? fmt::format(" in {} at {} m", layer.value("name", ""), number(layer["depth"], 0)) : "";
}

// Every formula's required thickness on the last snapshot, with its validity.
json formula_rows(const json& d, const json& wall) {
  json rows = json::array();
  if (wall.empty()) return rows;
  const json last = wall.back();
  const std::string governing = d.value("formula", "");
  for (const auto& f : formulas) {
    const json E = last["required_by"].value(f.key, json());
    const bool unset = std::string_view(f.key) == "plastic_mohr_coulomb" &&
                       !d.value("friction_angle", json()).is_number();
    rows.push_back({{"formula", std::string(f.label) + (f.key == governing ? " (governing)" : "")},
                    {"required", E.is_number() ? number(E, 2) + " m"
                                               : std::string(unset ? "– (no friction angle given)" : "invalid")},
                    {"valid_when", f.valid_when}});
  }
  return rows;
}

// Required against achieved over time: each layer, or the one run.
std::string wall_check_svg(const json& s) {
  std::vector<Series> series;
  auto add = [&](const json& summary, const std::string& name, std::size_t k) {
    Series req, got;
    for (const auto& w : summary.value("wall", json::array())) {
      const double day = w["day"].get<double>();
      req.x.push_back(day), got.x.push_back(day);
      req.y.push_back(w.value("required_thickness", json()).is_number() ? w["required_thickness"].get<double>() : NAN);
      got.y.push_back(achieved(w).is_number() ? achieved(w).get<double>() : NAN);
    }
    req.label = name + " required", got.label = name + " achieved";
    req.colour = got.colour = categorical_colours()[k % categorical_colours().size()];
    req.dashed = true, req.markers = got.markers = true;
    series.push_back(std::move(got));
    series.push_back(std::move(req));
  };
  if (s.contains("layers")) {
    std::size_t k = 0;
    for (const auto& l : s["layers"]) add(l, l["layer"].value("name", ""), k++);
  } else {
    add(s, "wall", 0);
  }
  Chart chart = line_chart("Required and achieved wall thickness", "time (d)", "thickness (m)", std::move(series));
  chart.y_include = {0.0};
  return render_svg(chart);
}

// One row per layer of a layered shaft: its wall on the last day and its verdict.
json layer_rows(const json& s) {
  json rows = json::array();
  for (const auto& l : s.value("layers", json::array())) {
    const json wall = l.value("wall", json::array());
    const json last = wall.empty() ? json::object() : wall.back();
    const json& layer = l["layer"];
    const json ld = l.value("design", json::object());
    const json T = last.contains("isotherm_mean_temperature") ? last["isotherm_mean_temperature"]
                                                              : last.value("mean_temperature_thinnest", json());
    rows.push_back(
        {{"name", layer.value("name", "")},
         {"governing", layer.value("governing", false) ? "governs" : ""},
         {"depth", number(layer["depth"], 0)},
         {"soil", layer.value("soil", "")},
         {"pressure", number(layer["pressure_MPa"], 2)},
         {"closure", number(l.value(keys::closure_time_days, json()), 1)},
         {"thinnest", number(achieved(last), 2)},
         {"mean_temperature", number(T, 1)},
         {"required", number(last.value("required_thickness", json()), 2)},
         {"utilisation", number(last.value("utilisation", json()), 2)},
         {"met_day", ld.value("met_day", json()).is_number() ? number(ld["met_day"], 0) : std::string("not met")},
         {"verdict", verdict(l, "")},
         {"report", layer.value("directory", "") + "/report.html"}});
  }
  return rows;
}

// The brine pipes: the film's note, the pipe wall's temperature and the
// heat extracted over time.
void add_brine(const json& b, json& view) {
  Series wall_T, heat;
  for (const auto& row : b.value("series", json::array())) {
    wall_T.x.push_back(row[0].get<double>()), wall_T.y.push_back(row[1].get<double>());
    heat.x.push_back(row[0].get<double>()), heat.y.push_back(row[2].get<double>());
  }
  wall_T.label = "pipe wall", heat.label = "heat extracted";
  view["brine_note"] = fmt::format(
      "Brine behind a film with h = {} W/(m² K): the pipe wall runs warmer than the brine by the heat it passes, "
      "q = h (T_wall − T_brine){}. Brine.csv has the series.",
      number(b["heat_transfer_coefficient"], 0),
      b.contains("annulus") ? fmt::format("; h from the annulus flow: Re = {}, Pr = {}, Nu = {} ({})",
                                          number(b["annulus"]["reynolds"], 0), number(b["annulus"]["prandtl"], 1),
                                          number(b["annulus"]["nusselt"], 2), b["annulus"].value("regime", ""))
                            : std::string());
  view["brine_svg"] = render_svg(line_chart("Pipe wall temperature", "time (d)", "temperature (°C)", {wall_T}));
  Chart q = line_chart("Heat extracted per metre of pipe", "time (d)", "heat (W/m)", {heat});
  q.y_include = {0.0};
  view["brine_heat_svg"] = render_svg(q);
}

}  // namespace

std::string design_verdict(const json& summary) {
  std::string where;
  if (summary.contains(keys::governing_layer))
    for (const auto& l : summary[keys::layers])
      if (l["layer"].value("governing", false)) where = layer_place(l["layer"]);
  return verdict(summary, where);
}

void add_design(const RunRecord& run, json& view) {
  const json& s = run.summary;
  const json d = s.value(keys::design, json::object());
  view["has_wall_check"] = d.contains(keys::met_day);
  for (const char* key : {"wall_check_note", "wall_check_svg", "brine_svg", "brine_heat_svg", "brine_note"})
    view[key] = "";
  view["formula_rows"] = json::array();
  view["layer_rows"] = json::array();
  view["has_layers"] = s.contains(keys::layers);
  view["has_brine"] = s.contains(keys::brine);
  if (d.contains(keys::met_day)) {
    const json wall = s.value(keys::wall, json::array());
    view["wall_check_note"] = fmt::format(
        "{}. The governing formula is {}; the lateral pressure {} MPa; the allowable strength is {} of the frozen soil's "
        "strength at the mean temperature of the wall on {}. Utilisation = required ÷ achieved thickness.",
        design_verdict(s), formula_label(d.value("formula", "")), number(d["pressure_MPa"], 3),
        number(d["allowable_factor"], 2), d.value("measured_on", std::string("the thinnest ray")));
    view["formula_rows"] = formula_rows(d, wall);
    view["wall_check_svg"] = wall_check_svg(s);
  }
  view["layer_rows"] = layer_rows(s);
  if (s.contains("brine")) add_brine(s["brine"], view);
}

}  // namespace frostwall::report::detail
