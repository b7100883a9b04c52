#include "study/study_erosion.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "report/nice_scale.hpp"
#include "report/svg_chart.hpp"
#include "report/view_numbers.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace keys = summary::keys;

using nlohmann::json;

namespace {

using report::get;
using report::number;
const json& soil(const VariantOutcome& v) { return v.summary[keys::soil]; }

// Lost grains over the count at the start, per second of the run.
double mean_loss_rate(const json& s) {
  const double start = get(s, "grains_at_start"), lost = get(s, "lost_to_cavity") + get(s, "washed_out");
  const auto& series = s["series"];
  const double t = series.empty() ? NAN : get(series.back(), "time");
  return start > 0 && t > 0 ? lost / start / t : NAN;
}

report::Chart overlay(const std::string& title, const std::string& y_label) {
  report::Chart c;
  c.title = title;
  c.x_label = "time (s)";
  c.y_label = y_label;
  c.x_include = {0.0};
  c.y_include = {0.0};
  return c;
}

}  // namespace

bool has_erosion(const StudyRun& run) {
  for (const auto& v : run.variants)
    if (v.ok && v.summary.value(keys::physics, std::string()) == "cfd-dem" && v.summary.contains(keys::soil))
      return true;
  return false;
}

void add_erosion(const StudyRun& run, json& view) {
  view["has_erosion"] = has_erosion(run);
  if (!view["has_erosion"].get<bool>()) return;
  json rows = json::array();
  report::Chart lost = overlay("grains lost, every variant", "grains lost (into the cavity and washed out)");
  report::Chart zone = overlay("porosity over the cavity, every variant", "porosity of the zone over the cavity");
  report::Chart settled = overlay("deepest surface settlement, every variant", "settlement (mm)");
  for (const auto& v : run.variants) {
    if (!v.ok || !v.summary.contains(keys::soil)) continue;
    const json& s = soil(v);
    const json& regime = s.value("regime", json::object());
    const auto& last = s["series"].empty() ? json::object() : s["series"].back();
    rows.push_back({{"name", v.name},
                    {"href", v.name + "/report.html"},
                    {"velocity", number(get(regime, "darcy_velocity_m_s"), 3)},
                    {"regime", regime.value("above_fluidisation", false) ? "above fluidisation: the inflow face boils"
                                                                         : "below fluidisation"},
                    {"cavity", number(get(s, "lost_to_cavity"), 0)},
                    {"washed", number(get(s, "washed_out"), 0)},
                    {"loss_rate", number(100.0 * mean_loss_rate(s), 2)},
                    {"settlement", number(1e3 * get(last, "settlement_max_m"), 1)},
                    {"width", number(1e3 * get(last, "settlement_width_m"), 0)},
                    {"cone", number(get(last, "cone_angle_deg"), 0)},
                    {"crater_depth", number(1e3 * get(last, "crater_depth_m"), 1)},
                    {"crater_slope", number(get(last, "crater_slope_deg"), 1)},
                    {"slip", number(get(last, "slip_surface_angle_deg"), 0)},
                    {"seconds", fmt::format("{:.1f}", v.seconds)}});
    report::Series a, b, c;
    a.label = b.label = c.label = v.name;
    for (const auto& r : s["series"]) {
      const double t = get(r, "time");
      a.x.push_back(t), b.x.push_back(t), c.x.push_back(t);
      a.y.push_back(get(r, "lost_to_cavity") + get(r, "washed_out"));
      b.y.push_back(get(r, "zone_porosity"));
      c.y.push_back(1e3 * get(r, "settlement_max_m"));
    }
    lost.series.push_back(a), zone.series.push_back(b), settled.series.push_back(c);
  }
  view["erosion_rows"] = rows;
  view["seed_rows"] = seed_spread(run);
  view["has_seed_spread"] = !view["seed_rows"].empty();
  view["erosion_charts"] = json::array(
      {{{"svg", report::render_svg(lost)},
        {"caption",
         "Grains that left the soil: fell into the cavity (kept there, or taken away where the cavity drains) or were washed out through the outflow face."}},
       {{"svg", report::render_svg(zone)},
        {"caption", "The cylinder over the cavity's crown to the surface; 1 when it is empty."}},
       {{"svg", report::render_svg(settled)},
        {"caption", "The deepest settlement of the surface along the line through the cavity."}}});
}

namespace {

// A variant's changes without its seed ("...seed = 3" parts): the variants
// that share it differ by their packing's seed alone.
std::pair<std::string, bool> without_seed(const std::string& changes) {
  std::string rest;
  bool seeded = false;
  std::size_t from = 0;
  while (from <= changes.size()) {
    const std::size_t end = std::min(changes.find("; ", from), changes.size());
    const std::string part = changes.substr(from, end - from);
    const std::size_t eq = part.find(" = ");
    const std::string path = part.substr(0, eq);
    if (eq != std::string::npos && path.size() >= 4 && path.compare(path.size() - 4, 4, "seed") == 0) seeded = true;
    else if (!part.empty()) rest += (rest.empty() ? "" : "; ") + part;
    from = end + 2;
  }
  return {rest.empty() ? "the base project" : rest, seeded};
}

// "mean ± sd" of a sample (sd with n - 1).
std::string spread(const std::vector<double>& x, double scale) {
  double mean = 0.0, squares = 0.0;
  for (double v : x) mean += scale * v / static_cast<double>(x.size());
  for (double v : x) squares += (scale * v - mean) * (scale * v - mean);
  return report::with_error(mean, std::sqrt(squares / static_cast<double>(x.size() - 1)), 1);
}

}  // namespace

json seed_spread(const StudyRun& run) {
  struct Group {
    std::vector<std::string> names;
    std::vector<double> lost, crater, settlement;
  };
  std::vector<std::pair<std::string, Group>> groups;
  for (const auto& v : run.variants) {
    if (!v.ok || !v.summary.contains(keys::soil)) continue;
    const auto [key, seeded] = without_seed(v.changes);
    if (!seeded) continue;
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == key; });
    if (it == groups.end()) it = groups.insert(groups.end(), {key, Group{}});
    const json& s = soil(v);
    const auto& last = s["series"].empty() ? json::object() : s["series"].back();
    it->second.names.push_back(v.name);
    it->second.lost.push_back(get(s, "lost_to_cavity") + get(s, "washed_out"));
    it->second.crater.push_back(get(last, "crater_depth_m"));
    it->second.settlement.push_back(get(last, "settlement_max_m"));
  }
  json rows = json::array();
  for (const auto& [key, g] : groups) {
    if (g.names.size() < 2) continue;
    std::string names;
    for (const auto& n : g.names) names += (names.empty() ? "" : ", ") + n;
    rows.push_back({{"changes", key},
                    {"variants", names},
                    {"seeds", g.names.size()},
                    {"lost", spread(g.lost, 1.0)},
                    {"crater_depth", spread(g.crater, 1e3)},
                    {"settlement", spread(g.settlement, 1e3)}});
  }
  return rows;
}

void write_erosion_csv(const std::filesystem::path& file, const StudyRun& run) {
  std::string text =
      "variant,darcy_velocity_m_s,above_fluidisation,lost_to_cavity,washed_out,mean_loss_rate_per_s,"
      "settlement_max_m,settlement_width_m,cone_angle_deg,run_s,crater_depth_m,crater_slope_deg,slip_surface_angle_deg\n";
  for (const auto& v : run.variants) {
    if (!v.ok || !v.summary.contains(keys::soil)) continue;
    const json& s = soil(v);
    const json& regime = s.value("regime", json::object());
    const auto& last = s["series"].empty() ? json::object() : s["series"].back();
    text += fmt::format("{},{},{},{},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.1f},{:.6g},{:.6g},{:.6g}\n", v.name,
                        get(regime, "darcy_velocity_m_s"), regime.value("above_fluidisation", false),
                        get(s, "lost_to_cavity"), get(s, "washed_out"), mean_loss_rate(s),
                        get(last, "settlement_max_m"), get(last, "settlement_width_m"), get(last, "cone_angle_deg"),
                        v.seconds, get(last, "crater_depth_m"), get(last, "crater_slope_deg"),
                        get(last, "slip_surface_angle_deg"));
  }
  io::write_text_file(file, text);
}

}  // namespace frostwall::study
