// The frost damage section of a porous plate's run (summary.json has
// "pores"): at each snapshot the temperature, the material (matrix, pore
// water, pore ice) and the damage side by side (the PD paper's Fig. 10);
// when each pore froze, as bars; the broken bonds and the largest damage
// over time (damage.csv); and a table of the pores.
#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/core.h>
#include <limits>

#include "report/cloud_raster.hpp"
#include "report/field_map.hpp"
#include "report/nice_scale.hpp"
#include "project/json_numbers.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"
#include "report/svg.hpp"
#include "report/svg_chart.hpp"

namespace frostwall::report::detail {

using project::number_or_nan;

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// A pore's saturation, marked when it lies below the critical saturation
// (its frozen water imposes nothing on the solid). Older summaries carry
// none: their pores were full.
std::string saturation_text(const json& pore) {
  const double S = pore.contains("saturation") ? number_or_nan(pore["saturation"]) : 1.0;
  const json& imposed = pore.contains("imposed_volume_change") ? pore["imposed_volume_change"] : json();
  return number(S, 3) + (imposed.is_number() && imposed.get<double>() <= 0.0 ? " \u2020" : "");
}

// A time or a measure to three significant digits, whole above 1000.
std::string short_number(double t) {
  if (!std::isfinite(t)) return "–";
  return std::abs(t) >= 1000 ? fmt::format("{:.0f}", t) : fmt::format("{:.3g}", t);
}

// Matrix, pore water, pore ice: apart in lightness too (mid, dark, light).
constexpr std::array<std::array<std::uint8_t, 3>, 3> material_colour{
    {{189, 181, 166}, {31, 104, 180}, {196, 234, 247}}};
constexpr std::array<const char*, 3> material_name{"matrix", "pore water", "pore ice"};

// The material map's legend, as tall as a colour bar.
std::string material_legend_svg() {
  std::string o = fmt::format(
      R"(<svg class="colour-bar" viewBox="0 0 340 58" width="340" height="58" role="img" font-family="{}" font-size="11">)"
      "<title>colours of the material map</title>",
      svg::font_family);
  double x = 24;
  for (std::size_t m = 0; m < material_name.size(); ++m) {
    const auto& c = material_colour[m];
    o += fmt::format(
        R"(<rect x="{}" y="6" width="18" height="14" fill="#{:02x}{:02x}{:02x}" stroke="#222" stroke-width="0.8"/>)"
        R"(<text x="{}" y="17" fill="#222">{}</text>)",
        svg::num(x), c[0], c[1], c[2], svg::num(x + 24), material_name[m]);
    x += 24 + svg::text_width(material_name[m], 11) + 18;
  }
  return o + R"(<text x="170" y="54" text-anchor="middle" fill="#222">material</text></svg>)";
}

// An area in m2 (per metre of depth) in µm2 or mm2, whichever reads
// better, with its share of the plate when the plate is known.
std::string area_text(double a, const RunRecord& run) {
  if (!std::isfinite(a)) return "–";
  const double v = a < 1e-6 ? 1e12 * a : 1e6 * a;
  std::string o =
      fmt::format("{} {}", v >= 1000 ? fmt::format("{:.0f}", v) : fmt::format("{:.3g}", v), a < 1e-6 ? "µm²" : "mm²");
  if (run.project)
    if (const auto* r = std::get_if<project::Rectangle>(&run.project->geometry); r && r->width * r->height > 0)
      o += fmt::format(", {:.3g} % of the plate", 100.0 * a / (r->width * r->height));
  return o;
}

struct DamageSeries {
  std::vector<double> time, broken_share, largest, area;
  std::string source;
};

// damage.csv (one row per mechanical equilibrium); else summary "damage" (one per snapshot).
DamageSeries damage_series(const RunRecord& run) {
  DamageSeries d;
  if (fs::exists(run.dir / "damage.csv")) {
    const CsvTable t = read_csv(run.dir / "damage.csv");
    auto column = [&](const char* name) {
      return t.column(name) ? *t.column(name) : std::vector<double>(t.rows(), nan);
    };
    d = {column("time"), column("broken_bond_share"), column("largest_damage"), column("damaged_area"), "damage.csv"};
    return d;
  }
  d.source = "summary.json";
  for (const auto& r : run.summary.value(keys::damage, json::array())) {
    d.time.push_back(number_or_nan(r.value("time", json())));
    d.broken_share.push_back(number_or_nan(r.value("broken_bond_share", json())));
    d.largest.push_back(number_or_nan(r.value("largest_damage", json())));
    d.area.push_back(number_or_nan(r.value("damaged_area", json())));
  }
  return d;
}

// The three maps of every snapshot of field.pvd, on one colour scale each.
void add_frost_maps(const RunRecord& run, const std::string& unit, json& view) {
  std::vector<std::pair<double, SolidSnapshot>> snapshots;
  std::vector<std::vector<double>> temperatures;
  for (const auto& e : read_pvd(run.dir / "field.pvd")) {
    SolidSnapshot s = read_solid(run.dir / e.file);
    const std::size_t n = s.particles.position.size();
    if (n == 0 || s.temperature.size() != n || s.material.size() != n) continue;
    if (!snapshots.empty() && n != snapshots.front().second.particles.position.size()) continue;
    temperatures.push_back(s.temperature);
    snapshots.emplace_back(e.time, std::move(s));
  }
  if (snapshots.empty()) {
    view["frost_maps_note"] =
        run.mechanics()
            ? "No snapshots with the pores' material in this directory (output.vtk off?), so no maps."
            : "No solid was modelled (no mechanics block): the temperature maps are above; there is no damage.";
    return;
  }
  const json facts = run.summary.value(keys::run, json::object());
  const auto& first = snapshots.front().second.particles;
  const double spacing = facts.value(keys::spacing, 0.0), h = smoothing_length(facts);
  // A square window over the plate (its particles' extent).
  const MapWindow window = window_over(first.position, spacing, 300);
  const FieldMap map(first, WedgeSymmetry{}, facts.value("kernel", "wendland_c2"), h, spacing, window, 0.0);
  const CloudRaster cloud(first.position, triangle_edge(facts), window);
  const double freezing_point = run.freezing_point();
  const ColourScale temperature = temperature_scale(temperatures, freezing_point), damage(0.0, 1.0, 0.5);
  json rows = json::array();
  for (const auto& [t, s] : snapshots) {
    std::vector<std::array<std::uint8_t, 3>> colours;
    colours.reserve(s.material.size());
    for (int m : s.material) colours.push_back(material_colour[std::size_t(std::clamp(m, 0, 2))]);
    const std::string title = fmt::format("t = {:g} {}", t, unit);
    json maps = json::array();
    maps.push_back(
        {{"html", map_html(cloud.raster(s.temperature, temperature), window, "temperature", {}, MapOverlay{}, title)},
         {"caption", fmt::format("temperature (°C) at {:g} {}", t, unit)}});
    maps.push_back({{"html", map.html(map.nearest_raster(colours), "material", {}, true, MapOverlay{}, title)},
                    {"caption", fmt::format("matrix, pore water and pore ice at {:g} {}", t, unit)}});
    maps.push_back({{"html", map_html(cloud.raster(s.damage, damage), window, "damage", {}, MapOverlay{}, title)},
                    {"caption", fmt::format("damage (share of broken bonds) at {:g} {}", t, unit)}});
    rows.push_back({{"maps", maps}});
  }
  view["frost_snapshots"] = rows;
  view["frost_has_maps"] = true;
  view["frost_temperature_bar_svg"] = temperature.colour_bar_svg(340);
  view["frost_material_legend_svg"] = material_legend_svg();
  view["frost_damage_bar_svg"] = damage.colour_bar_svg(340, "damage (share of broken bonds)");
  view["frost_maps_note"] = fmt::format(
      "Each snapshot of the plate: the temperature (blue to red at the pore water's freezing point, {} °C) and the "
      "damage on the particles' triangles, linear within each (as ParaView draws the VTK cells); the material is each "
      "particle's own, its nearest pixels taking its colour, so water and ice do not blend.",
      number(freezing_point, 1));
}

Chart damage_chart(const DamageSeries& d, bool percent, double all_frozen, const std::string& unit) {
  Chart c;
  c.title = percent ? "Broken bonds over time" : "Largest damage over time";
  c.x_label = "time (" + unit + ")";
  c.y_label = percent ? "broken bonds (% of all)" : "largest damage (share of bonds)";
  Series s;
  s.x = d.time;
  s.y = percent ? d.broken_share : d.largest;
  if (percent)
    for (double& v : s.y) v *= 100.0;
  s.colour = percent ? categorical_colours()[1] : categorical_colours()[0];
  s.markers = d.time.size() <= 40;
  c.series.push_back(std::move(s));
  c.x_include = {0.0};
  c.y_include = percent ? std::vector<double>{0.0} : std::vector<double>{0.0, 1.0};
  if (std::isfinite(all_frozen)) c.guides.push_back({true, all_frozen, "all pores frozen"});
  c.empty_note = "no mechanical equilibria recorded";
  c.width = 500, c.height = 300;
  return c;
}

// The crack measures of each snapshot (summary "damage" and "cracks"),
// with what converged PD gives for a pushed rim.
void add_crack_table(const RunRecord& run, json& view) {
  json rows = json::array();
  const json& cracks = run.summary.value("cracks", json::array());
  for (const auto& d : run.summary.value(keys::damage, json::array())) {
    if (!d.contains("crack_length")) continue;  // older summaries
    const std::size_t k = rows.size();
    rows.push_back({{"time", short_number(number_or_nan(d.value("time", json())))},
                    {"broken", number(100.0 * number_or_nan(d.value("broken_bond_share", json())), 3)},
                    {"length", short_number(1e6 * number_or_nan(d["crack_length"]))},
                    {"per_area", short_number(1e-3 * number_or_nan(d.value("crack_length_per_area", json())))},
                    {"energy", short_number(1e3 * number_or_nan(d.value("broken_bond_energy", json())))},
                    {"file", k < cracks.size() ? cracks[k].value("file", "") : ""}});
  }
  view["crack_rows"] = rows;
  view["has_crack_rows"] = !rows.empty();
  view["crack_note"] =
      "A crack is where the damage (the share of a particle's bonds that broke) exceeds 0.4; the crack lines are that "
      "level's isolines (cracks_XXXX.vtp), and their length counts both faces of a thin crack band, so it is about "
      "twice the crack's own length. The broken-bond energy is the work the broken bonds took, G0 per unit length of a "
      "straight crack. The crack reach in the pore table is the farthest cracked point from a pore's rim, in its "
      "radii. Cracks of a full pore run several radii into the matrix: a rim pushed out by u keeps the matrix's hoop "
      "stress 2 G u r0 / r^2 above its tensile strength out to r = sqrt(2 G u r0 / f_t), many radii for mortar, and the "
      "cracks stop where they have relieved it; damage confined to the rims and the ligaments between pores is what a "
      "coarse or unconverged model shows, not what the equations give.";
}

}  // namespace

void add_frost(const RunRecord& run, json& view) {
  view["has_frost"] = false;
  view["frost_has_maps"] = false;
  view["has_crack_rows"] = false;
  for (const char* key : {"frost_snapshots", "frost_charts", "pore_rows", "crack_rows"}) view[key] = json::array();
  for (const char* key :
       {"frost_note", "frost_maps_note", "frost_temperature_bar_svg", "frost_material_legend_svg",
        "frost_damage_bar_svg", "pore_bars_svg", "pore_bars_caption", "frost_time_unit", "crack_note"})
    view[key] = "";
  if (!run.summary.contains(keys::pores) || !run.summary[keys::pores].is_array()) return;
  view["has_frost"] = true;
  const auto& pores = run.summary[keys::pores];
  const std::string unit = run.summary.value(keys::run, json::object()).value("time_unit", "s");
  view["frost_time_unit"] = unit;
  const double all_frozen = number_or_nan(run.summary.value("all_pores_frozen", json()));
  const DamageSeries d = damage_series(run);

  // The end of the run, where unfinished freezing bars stop.
  double end = run.project ? run.project->time.end / run.project->time.unit_seconds() : nan;
  if (!std::isfinite(end)) {
    end = all_frozen;
    for (double t : d.time) end = std::isfinite(end) ? std::max(end, t) : t;
  }

  // When each pore froze, as listed; the table beside.
  BarChart bars;
  bars.title = "Freezing of each pore";
  bars.x_label = "time (" + unit + ")";
  bars.x_include = {0.0};
  bars.open_end = end;
  bars.never_started = "not started within the run";
  if (std::isfinite(all_frozen)) bars.guides.push_back({true, all_frozen, "all pores frozen"});
  json rows = json::array();
  std::size_t started = 0, finished = 0;
  double first_start = nan;
  for (const auto& p : pores) {
    const std::string id = p.contains("id") ? p["id"].dump() : std::to_string(rows.size());
    const double start = number_or_nan(p.value("freezing_start", json())),
                 stop = number_or_nan(p.value("freezing_end", json()));
    bars.bars.push_back({"pore " + id, start, stop});
    started += std::isfinite(start), finished += std::isfinite(start) && std::isfinite(stop);
    if (std::isfinite(start)) first_start = std::isfinite(first_start) ? std::min(first_start, start) : start;
    rows.push_back(
        {{"pore", id},
         {"centre_x", number(1e6 * number_or_nan(p.value("x", json())), 1)},
         {"centre_y", number(1e6 * number_or_nan(p.value("y", json())), 1)},
         {"radius", number(1e6 * number_or_nan(p.value("radius", json())), 1)},
         {"saturation", saturation_text(p)},
         {"freezing_start", short_number(start)},
         {"freezing_end", short_number(stop)},
         {"max_rim_damage", number(p.value("max_rim_damage", json()), 2)},
         {"crack_reach",
          number(number_or_nan(p.value("crack_reach", json())) / number_or_nan(p.value("radius", json())), 2)}});
  }
  bars.width = 720;
  view["pore_rows"] = rows;
  view["pore_saturation_note"] =
      "Saturation: the share of each pore's volume its water fills. Ice takes (1 + dV) times the volume of its water "
      "(1.09 for water), so a pore below the critical saturation 1 / (1 + dV) (0.917 for water; marked \u2020) freezes "
      "into its own air and does not load the solid; above it the solid takes the excess, (1 + dV) S - 1 of the pore's "
      "volume.";
  view["pore_bars_svg"] = render_svg(bars);
  view["pore_bars_caption"] = fmt::format(
      "Each pore from its first ice to fully frozen, in the order of the list{}. A fading bar without a right end is still "
      "freezing at the end of the run ({} {}).",
      std::isfinite(all_frozen) ? "; dashed: all pores frozen" : "", short_number(end), unit);

  // Damage over time (none without mechanics).
  const std::string source = d.source == "damage.csv" ? "damage.csv, one point per mechanical equilibrium"
                                                      : "summary.json, one point per snapshot";
  if (!d.time.empty())
    view["frost_charts"] =
        json::array({{{"id", "frost-broken-bonds"},
                      {"title", "Broken bonds"},
                      {"svg", render_svg(damage_chart(d, true, all_frozen, unit))},
                      {"caption", "Broken bonds as a share of all bonds of the plate (" + source + ")."}},
                     {{"id", "frost-largest-damage"},
                      {"title", "Largest damage"},
                      {"svg", render_svg(damage_chart(d, false, all_frozen, unit))},
                      {"caption", "The largest damage of any particle, its share of broken bonds (" + source + ")."}}});

  std::string note = fmt::format("{} water-filled pores; ", pores.size());
  if (std::isfinite(all_frozen)) note += fmt::format("all frozen at {} {}", short_number(all_frozen), unit);
  else note += fmt::format("{} of them fully frozen within the run, {} started", finished, started);
  if (std::isfinite(first_start)) note += fmt::format(" (the first ice at {} {})", short_number(first_start), unit);
  note += ".";
  if (!d.time.empty())
    note +=
        fmt::format(" At {} {}: {:.3g} % of the bonds broken, largest damage {}, damaged area (damage above 0.4) {}.",
                    short_number(d.time.back()), unit, 100.0 * d.broken_share.back(), number(d.largest.back(), 2),
                    area_text(d.area.back(), run));
  view["frost_note"] = note;
  add_crack_table(run, view);
  add_frost_maps(run, unit, view);
}

}  // namespace frostwall::report::detail
