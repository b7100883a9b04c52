// The report's seepage-erosion section (a CFD-DEM run over a cavity): the
// packing's regime said plainly, the grains lost and how, the zone over
// the cavity, point A, the surface's settlement profile, and maps of the
// grains' displacement on the mid-section through the cavity at the
// snapshots (the CFD-DEM paper's Fig. 5).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <fmt/format.h>

#include "report/colour_scale.hpp"
#include "report/grain_render.hpp"
#include "report/report_sections.hpp"
#include "report/run_files.hpp"
#include "report/svg_chart.hpp"

namespace frostwall::report::detail {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

Series series_of(const json& rows, const std::string& label, const std::function<double(const json&)>& y) {
  Series s;
  s.label = label;
  for (const auto& r : rows) s.x.push_back(get(r, "time")), s.y.push_back(y(r));
  return s;
}

// Grains within a diameter of the plane x = x0 (the y-z mid-section),
// drawn to scale as circles coloured by |displacement|.
std::string section_svg(const GrainSnapshot& g, double x0, const std::array<double, 4>& window,
                        const ColourScale& colours) {
  const double width = 300.0, scale = width / (window[1] - window[0]);
  const double height = (window[3] - window[2]) * scale;
  std::string svg = fmt::format(R"(<svg viewBox="0 0 {:.0f} {:.0f}" width="{:.0f}" height="{:.0f}" role="img">)", width,
                                height, width, height);
  svg += fmt::format(R"(<rect width="{:.0f}" height="{:.0f}" fill="#f4f4f4"/>)", width, height);
  for (std::size_t i = 0; i < g.position.size(); ++i) {
    const auto& p = g.position[i];
    if (std::abs(p[0] - x0) > 0.5 * g.diameter[i]) continue;
    const auto c = colours(g.displacement[i]);
    svg += fmt::format(R"svg(<circle cx="{:.1f}" cy="{:.1f}" r="{:.2f}" fill="rgb({},{},{})"/>)svg",
                       (p[1] - window[0]) * scale, (window[3] - p[2]) * scale, 0.5 * g.diameter[i] * scale, c[0], c[1],
                       c[2]);
  }
  return svg + "</svg>";
}

// The last snapshot in 3-D: the whole block from above a corner (the
// surface's trough), and cut through the cavity's centre across the flow's
// section plane, seen from the cut side (the collapse cone inside).
json grain_views(const GrainSnapshot& g, const project::CfdDem& c, const ColourScale& scale) {
  std::vector<std::array<std::uint8_t, 3>> colour(g.position.size());
  for (std::size_t i = 0; i < colour.size(); ++i) colour[i] = scale(g.displacement[i]);
  GrainView whole;
  whole.up_axis = project::gravity_axis(c);
  GrainView cut = whole;
  cut.cut_axis = (whole.up_axis + 1) % 3;
  cut.cut_at = c.cavity->centre[std::size_t(cut.cut_axis)];
  cut.azimuth_deg = 215.0;
  const char* axis = "xyz";
  auto seen_from = [&](const GrainView& v) {  // the camera's side, in the model's axes
    const double az = v.azimuth_deg * std::numbers::pi / 180.0;
    const int a1 = (v.up_axis + 1) % 3, a2 = (v.up_axis + 2) % 3;
    return fmt::format("seen from {}{}, {}{}, {:.0f}° above the horizontal", std::cos(az) < 0 ? "−" : "+", axis[a1],
                       std::sin(az) < 0 ? "−" : "+", axis[a2], v.elevation_deg);
  };
  json views = json::array();
  for (const auto& [v, caption] : {std::pair{whole, "the whole block, " + seen_from(whole)},
                                   std::pair{cut, fmt::format("cut at {} = {:.3g} m through the cavity's centre, {}",
                                                              axis[cut.cut_axis], cut.cut_at, seen_from(cut))}})
    views.push_back({{"png", png_data_uri(render_grains(g.position, g.diameter, colour, c.box.low, c.box.high, v))},
                     {"width", v.width},
                     {"height", v.height},
                     {"caption", caption}});
  return views;
}

std::string or_dash(const json& v, const char* format_spec, double scale = 1.0) {
  return v.is_number() ? fmt::format(fmt::runtime(format_spec), scale * v.get<double>()) : std::string("–");
}

json erosion_facts(const json& s, bool drain) {
  json facts = json::array(
      {{{"label", "grains at the start"}, {"value", fmt::format("{:.0f}", get(s, "grains_at_start"))}},
       {{"label", drain ? "fell into the cavity (taken away by the leak)" : "fell into the cavity (kept there)"},
        {"value", fmt::format("{:.0f}", get(s, "lost_to_cavity"))}}});
  if (!drain) {
    const json& cavity = s.value("cavity", json::object());
    facts.push_back({{"label", "in the cavity at the end, of the most it holds"},
                     {"value", fmt::format("{:.0f} of {:.0f}", get(s, "grains_in_cavity_at_end"),
                                           get(cavity, "capacity_grains"))}});
  }
  facts.push_back(
      {{"label", "washed out through the outflow face"}, {"value", fmt::format("{:.0f}", get(s, "washed_out"))}});
  if (const json& cr = s.value("crater", json::object()); !cr.empty()) {
    facts.push_back(
        {{"label", "crater: depth and width below the surrounding ground"},
         {"value", or_dash(cr["depth_m"], "{:.1f} mm", 1e3) + ", " + or_dash(cr["width_m"], "{:.0f} mm", 1e3)}});
    facts.push_back({{"label", "crater: flank slope (10-90 % of the depth), trough volume"},
                     {"value", or_dash(cr["slope_deg"], "{:.1f} deg") + ", " + or_dash(cr["volume_m3"], "{:.3g} m3")}});
  }
  facts.push_back({{"label", "slip surface from the horizontal"},
                   {"value", or_dash(s.value("slip_surface_angle_deg", json()), "{:.0f} deg")}});
  facts.push_back({{"label", "point A"}, {"value", s.contains("point_a") ? s["point_a"].dump() : "–"}});
  return facts;
}

// The crater's two flanks at the end drawn on the settlement profile.
void add_crater_flanks(const json& s, Chart& profile) {
  const json& cr = s.value("crater", json::object());
  if (cr.empty() || !cr["depth_m"].is_number()) return;
  const double depth_mm = 1e3 * cr["depth_m"].get<double>();
  const double base_mm = 1e3 * cr.value("base_m", 0.0);  // the surrounding ground's own settlement
  for (const char* side : {"low_side", "high_side"}) {
    if (!cr[side].is_object()) continue;
    Series flank;
    flank.label =
        side == std::string("low_side") ? fmt::format("flanks, {} mean", or_dash(cr["slope_deg"], "{:.1f} deg")) : "";
    flank.colour = "#333333";
    flank.dashed = true;
    flank.x = {cr[side]["foot_m"].get<double>(), cr[side]["x_90_percent_m"].get<double>()};
    flank.y = {base_mm, base_mm + 0.9 * depth_mm};
    profile.series.push_back(flank);
  }
}

// The headline: the loss and the crater.
json erosion_cards(const json& s, bool drain) {
  json cards = json::array();
  cards.push_back(card(
      "Fell into the cavity", fmt::format("{:.0f} grains", get(s, "lost_to_cavity")),
      fmt::format("of {:.0f} at the start{}", get(s, "grains_at_start"), drain ? "; the leak takes them away" : "")));
  cards.push_back(card("Washed out", fmt::format("{:.0f} grains", get(s, "washed_out")), "through the outflow face"));
  if (const json& cr = s.value("crater", json::object()); !cr.empty())
    cards.push_back(
        card("Crater", or_dash(cr["depth_m"], "{:.1f} mm", 1e3) + " deep",
             or_dash(cr["width_m"], "{:.0f} mm", 1e3) + " wide, flanks at " + or_dash(cr["slope_deg"], "{:.1f} deg")));
  return cards;
}

// The surface's settlement along x through the cavity at each profile's
// time, with the crater's flanks at the end.
Chart settlement_profile(const json& s, const project::CfdDem& c) {
  Chart profile = line_chart("Surface settlement over the cavity", "x (m)", "settlement (mm)", {});
  for (const auto& p : s.value("surface_profiles", json::array())) {
    Series line;
    line.label = fmt::format("{:.2f} s", p["time"].get<double>());
    for (const auto& b : p["settlement"])
      line.x.push_back(b[0].get<double>()), line.y.push_back(1e3 * b[1].get<double>());
    profile.series.push_back(line);
  }
  profile.guides.push_back({true, c.cavity->centre[0], "cavity"});
  add_crater_flanks(s, profile);
  return profile;
}

// The curves over time of soil.series, and the settlement profile.
json erosion_charts(const json& s, const project::CfdDem& c) {
  const json& rows = s["series"];
  json charts = json::array();
  auto add = [&](const std::string& id, const Chart& ch, const std::string& caption) {
    charts.push_back({{"id", id}, {"title", ch.title}, {"svg", render_svg(ch)}, {"caption", caption}});
  };
  add("lost",
      line_chart("Grains lost", "time (s)", "grains",
                 {series_of(rows, "into the cavity", [](const json& r) { return get(r, "lost_to_cavity"); }),
                  series_of(rows, "washed out", [](const json& r) { return get(r, "washed_out"); })}),
      "Cumulative; the loss rate of an interval is its loss over the grains in the soil at its start (summary.json, soil.csv).");
  add("loss_rate",
      line_chart("Loss rate", "time (s)", "grains lost per grain in the soil, per output interval",
                 {series_of(rows, "", [](const json& r) { return get(r, "loss_rate"); })}),
      "");
  add("zone",
      line_chart("Porosity over the cavity", "time (s)", "porosity",
                 {series_of(rows, "", [](const json& r) { return get(r, "zone_porosity"); })}),
      "The cylinder of the cavity's radius from its crown to the surface: 1 when its grains are gone.");
  add("contacts",
      line_chart("Change of contacts", "time (s)", "contacts gained since the last output",
                 {series_of(rows, "", [](const json& r) { return get(r, "contact_change"); })}),
      "");
  add("point_a",
      line_chart("Point A: pressure drop from the inflow face", "time (s)", "Pa",
                 {series_of(rows, "", [](const json& r) { return get(r, "pressure_drop_to_a_Pa"); })}),
      "");
  add("forces_a",
      line_chart("Point A's cell: mean force per grain", "time (s)", "N (magnitude)",
                 {series_of(rows, "drag",
                            [](const json& r) {
                              return std::hypot(r["mean_drag_at_a_N"][0].get<double>(),
                                                r["mean_drag_at_a_N"][1].get<double>(),
                                                r["mean_drag_at_a_N"][2].get<double>());
                            }),
                  series_of(rows, "pressure gradient",
                            [](const json& r) {
                              const auto& f = r["mean_pressure_gradient_force_at_a_N"];
                              return std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>());
                            }),
                  series_of(rows, "buoyancy",
                            [](const json& r) {
                              const auto& f = r["mean_buoyancy_at_a_N"];
                              return std::hypot(f[0].get<double>(), f[1].get<double>(), f[2].get<double>());
                            })}),
      "");
  add("settlement", settlement_profile(s, c),
      "Along x through the cavity: the surface's drop since the run started (its highest grain in bins of two "
      "diameters). Dashed: the crater's flanks at the end, the straight line through 10 % and 90 % of its depth "
      "below the surrounding ground on each side (from columns one diameter wide), down to that ground.");
  Chart cone = line_chart("Collapse zone", "time (s)", "grains displaced more than two diameters",
                          {series_of(rows, "", [](const json& r) { return get(r, "displaced_grains"); })});
  add("collapse", cone,
      "The boundary of the grains moved more than one diameter, fitted against height, is the slip surface "
      "(slip_surface_angle_deg in summary.json; cone_angle_deg is the same for two diameters).");
  return charts;
}

// Displacement on the mid-section x = cavity centre, one map per
// snapshot, the last snapshot in 3-D, and their colour bar.
void add_displacement_maps(const RunRecord& run, const project::CfdDem& c, json& view) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(run.dir))
    if (e.path().filename().string().starts_with("grains_") && e.path().extension() == ".vtu")
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::vector<GrainSnapshot> snaps;
  double largest = 0.0;
  for (const auto& f : files) {
    snaps.push_back(read_grains(f));
    for (double d : snaps.back().displacement) largest = std::max(largest, d);
  }
  const ColourScale colours(0.0, std::max(largest, 1e-6), -1.0);
  json maps = json::array();
  const std::array<double, 4> window = {c.box.low[1], c.box.high[1], c.box.low[2], c.box.high[2]};
  const auto& times = run.summary.value("snapshots", json::array());
  for (std::size_t k = 0; k < snaps.size(); ++k)
    if (!snaps[k].position.empty())
      maps.push_back(
          {{"html", section_svg(snaps[k], c.cavity->centre[0], window, colours)},
           {"caption",
            fmt::format("{} s", k < times.size() ? fmt::format("{:.3g}", times[k]["time"].get<double>()) : "?")}});
  view["erosion_maps"] = maps;
  view["erosion_views"] = json::array();
  if (!snaps.empty() && !snaps.back().displacement.empty())
    view["erosion_views"] = grain_views(snaps.back(), c, colours);
  view["has_erosion_views"] = !view["erosion_views"].empty();
  view["erosion_colour_bar"] = maps.empty() ? "" : colours.colour_bar_svg(320, "displacement (m)");
}

}  // namespace

void add_erosion(const RunRecord& run, json& view) {
  const json& s = run.summary.value("soil", json::object());
  const bool cavity = run.project && run.project->cfd_dem && run.project->cfd_dem->cavity;
  view["has_erosion"] = cavity && s.contains("series");
  if (!view["has_erosion"].get<bool>()) return;
  const auto& c = *run.project->cfd_dem;
  const json& regime = s.value("regime", json::object());
  view["erosion_regime"] =
      regime.value("note", fmt::format("packing porosity {:.3f}, critical gradient {:.2f}, "
                                       "Ergun's minimum fluidisation velocity {:.3g} m/s (still water)",
                                       get(regime, "porosity"), get(regime, "critical_gradient"),
                                       get(regime, "minimum_fluidisation_velocity_m_s")));
  view["erosion_boils"] = regime.value("above_fluidisation", false);
  view["erosion_facts"] = erosion_facts(s, c.cavity->drain);
  view["cards"] = erosion_cards(s, c.cavity->drain);
  view["has_cards"] = true;
  view["erosion_charts"] = erosion_charts(s, c);
  add_displacement_maps(run, c, view);
}

}  // namespace frostwall::report::detail
