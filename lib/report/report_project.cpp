// The project section: what was asked for, as the engineer wrote it.
#include <cmath>
#include <fmt/core.h>
#include <fmt/ranges.h>
#include <numbers>

#include "geometry/layout.hpp"
#include "report/layout_drawing.hpp"
#include "report/report_sections.hpp"
#include "report/svg_chart.hpp"
#include "thermal/phase_change.hpp"
#include "geometry/interface_planes.hpp"

namespace frostwall::report::detail {

using nlohmann::json;

namespace {

constexpr double day = project::seconds_per_day;

std::string pattern_name(project::Pattern p) {
  switch (p) {
    case project::Pattern::single: return "single ring";
    case project::Pattern::three_hole: return "three-hole double ring (inner ring rotated by half a spacing)";
    case project::Pattern::four_hole: return "four-hole double ring (inner ring with twice the pipes)";
    case project::Pattern::rings: return "rings";
    case project::Pattern::pipes: return "measured pipe positions";
  }
  return "";
}

std::string conductivity(const project::PhaseProperties& p) {
  return p.anisotropic() ? number(p.conductivity[0], 2) + " / " + number(p.conductivity[1], 2) + " (x / y)"
                         : number(p.conductivity[0], 2);
}

void add_layout(const RunRecord& run, const project::ShaftSection& section, json& view) {
  const auto pipes = geometry::pipe_positions(section.layout);
  const auto& L = section.layout;
  json rows = json::array();
  rows.push_back(row("pattern", pattern_name(L.pattern)));
  if (L.pattern == project::Pattern::single || L.pattern == project::Pattern::three_hole ||
      L.pattern == project::Pattern::four_hole) {
    const auto& o = L.outer_ring;
    rows.push_back(row("outer ring", fmt::format("{} pipes on r = {} m, first at {}°, spacing {} m", o.count,
                                                 number(o.radius, 2), number(o.offset_deg, 1),
                                                 number(2 * std::numbers::pi * o.radius / std::max(o.count, 1), 3))));
    if (L.inner_ring_radius) {
      const int n = L.pattern == project::Pattern::four_hole ? 2 * o.count : o.count;
      rows.push_back(row("inner ring", fmt::format("{} pipes on r = {} m", n, number(*L.inner_ring_radius, 2))));
    }
  } else if (L.pattern == project::Pattern::rings) {
    for (std::size_t k = 0; k < L.rings.size(); ++k)
      rows.push_back(
          row(fmt::format("ring {}", k), fmt::format("{} pipes on r = {} m, first at {}°", L.rings[k].count,
                                                     number(L.rings[k].radius, 2), number(L.rings[k].offset_deg, 1))));
  }
  rows.push_back(
      row("pipes", fmt::format("{} in all, outer diameter {} mm ({} model)", geometry::all_pipe_positions(L).size(),
                               number(section.pipe.diameter * 1000, 1), project::pipe_model_name(section.pipe.model))));
  if (!L.failed_pipes.empty())
    rows.push_back(row("failed pipes", fmt::format("{} (off; ground like the rest)", fmt::join(L.failed_pipes, ", "))));
  if (section.shaft.excavation_radius)
    rows.push_back(row("excavation radius", number(*section.shaft.excavation_radius, 2) + " m"));
  if (const auto& e = run.project->excavation) {
    const std::string when = e->rate
                                 ? fmt::format("from day {} at {} m/d", number(e->start_day, 1), number(*e->rate, 2))
                                 : std::string("on the days given");
    std::string sinking = fmt::format("{}; air {} °C at first, film {} W/(m² K)", when,
                                      number(e->air_temperature.points.front().second, 1), number(e->heat_transfer, 1));
    if (e->lining)
      sinking += fmt::format("; a {} m lining {} d behind, {} kJ/kg of hydration heat", number(e->lining->thickness, 2),
                             number(e->lining->placed_after / 86400.0, 1),
                             number(e->lining->hydration.final() / 1e3, 0));
    rows.push_back(row("sinking", sinking));
  }
  const WedgeSymmetry w = wedge_of(run.summary);
  const bool symmetric = run.project->numerics.use_symmetry && w.mirror_lines > 0;
  rows.push_back(row("simulated", symmetric ? fmt::format("a wedge of {}° between two of {} mirror lines, from {}°",
                                                          number(w.angle * 180 / std::numbers::pi, 3), w.mirror_lines,
                                                          number(w.start * 180 / std::numbers::pi, 2))
                                            : std::string("the full circle")));
  view["layout_rows"] = rows;

  LayoutDrawing drawing;
  drawing.section = &section;
  drawing.pipes = geometry::all_pipe_positions(section.layout);
  drawing.wedge = symmetric ? w : WedgeSymmetry{};
  if (!pipes.empty()) {
    const auto planes = geometry::interface_planes(pipes);
    drawing.OA = planes.OA, drawing.OB = planes.OB;
  }
  drawing.sensors = run.project->monitoring;
  view["layout_svg"] = layout_svg(drawing);
  view["layout_caption"] =
      "Plan view. Shaded: the wedge the solver simulated (its sides are mirror planes of the layout). "
      "OA runs through a pipe of the outer ring, OB halfway to the next one, where the wall is thinnest.";
}

// A chart of the project section's size (one dark line follows).
Chart small_chart(const std::string& title, const std::string& x_label, const std::string& y_label) {
  Chart chart;
  chart.title = title;
  chart.x_label = x_label;
  chart.y_label = y_label;
  chart.width = 440, chart.height = 220;
  return chart;
}

// The freezing curve in words, with its parameters and source.
std::string curve_text(const project::Soil& s) {
  const auto& c = s.freezing_curve;
  switch (c.model) {
    case project::CurveModel::exponential:
      return fmt::format("exponential, S_w = {} + {} exp(-((T - Tf)/{} K)²) (InterFrost)",
                         number(c.residual_saturation, 3), number(1.0 - c.residual_saturation, 3), number(c.width, 3));
    case project::CurveModel::power:
      return fmt::format("power law, unfrozen water {} θ^{} of {} kg/kg (Anderson and Tice)", number(c.alpha, 4),
                         number(c.beta, 3), number(c.water_content, 4));
    case project::CurveModel::linear: return "linear over the freezing range";
    default: return "step (all at the freezing point)";
  }
}

// The liquid fraction against temperature, as the solver holds it, from
// 3 K above the freezing point down past where three quarters of the
// freezable water is ice.
json curve_svg(const project::Soil& s) {
  if (s.latent_heat <= 0.0) return false;
  const thermal::PhaseChangeLaw law(s);
  double low = law.frozen_temperature() - 1.0;
  if (law.tabulated())
    while (low > law.freezing_point() - 60.0 && law.liquid_fraction(law.enthalpy(low)) > 0.25) low -= 0.5;
  low = std::min(low, s.freezing_point - s.freezing_range - 1.0);
  const double high = s.freezing_point + 3.0;
  Chart chart = small_chart("freezing curve", "temperature (°C)", "liquid share of the pore water");
  Series curve{"", {}, {}, "#0b3c73", false, true};
  for (int k = 0; k <= 400; ++k) {
    const double T = low + (high - low) * k / 400.0;
    curve.x.push_back(T);
    curve.y.push_back(law.liquid_fraction(law.enthalpy(T)));
  }
  chart.series.push_back(curve);
  return render_svg(chart);
}

void add_soil(const project::Soil& s, json& view) {
  const auto vol = [&](const project::PhaseProperties& p) { return s.density * p.heat_capacity; };
  const auto alpha = [&](const project::PhaseProperties& p) { return p.conductivity[0] / vol(p) * 1e6; };
  view["soil_name"] = s.name;
  view["soil_rows"] = json::array({
      {{"property", "thermal conductivity"},
       {"unfrozen", conductivity(s.unfrozen)},
       {"frozen", conductivity(s.frozen)},
       {"unit", "W/(m K)"}},
      {{"property", "specific heat capacity"},
       {"unfrozen", number(s.unfrozen.heat_capacity, 1)},
       {"frozen", number(s.frozen.heat_capacity, 1)},
       {"unit", "J/(kg K)"}},
      {{"property", "volumetric heat capacity"},
       {"unfrozen", number(vol(s.unfrozen) / 1e6, 3)},
       {"frozen", number(vol(s.frozen) / 1e6, 3)},
       {"unit", "MJ/(m³ K)"}},
      {{"property", "thermal diffusivity"},
       {"unfrozen", number(alpha(s.unfrozen), 3)},
       {"frozen", number(alpha(s.frozen), 3)},
       {"unit", "10⁻⁶ m²/s"}},
  });
  view["soil_common"] = json::array({
      row("density", number(s.density, 0) + " kg/m³"),
      row("latent heat", number(s.latent_heat, 1) + " J/kg (" + number(s.latent_heat * s.density / 1e6, 1) + " MJ/m³)"),
      row("freezing point", number(s.freezing_point, 2) + " °C"),
      row("freezing range", s.freezing_range > 0 ? number(s.freezing_range, 2) + " K below the freezing point"
                                                 : std::string("none (isothermal)")),
      row("freezing curve", curve_text(s)),
  });
  view["soil_curve_svg"] = curve_svg(s);
}

void add_schedule(const project::Project& p, const project::TemperatureSchedule& schedule, json& view) {
  json rows = json::array();
  for (const auto& [t, T] : schedule.points)
    rows.push_back({{"day", number(t / day, 1)}, {"temperature", number(T, 1)}});
  view["schedule_rows"] = rows;
  view["schedule_note"] = schedule.constant()
                              ? "Constant over the run."
                              : "Linear between the points, held at the first and last value outside them.";
  view["schedule_svg"] = false;
  if (schedule.constant()) return;
  Chart chart = small_chart("pipe wall temperature over time", "time (d)", "pipe wall (°C)");
  Series s{"", {}, {}, "#0b3c73", false, true};
  std::vector<double> t{0.0};
  for (const auto& pt : schedule.points) t.push_back(pt.first);
  t.push_back(p.time.end);
  std::sort(t.begin(), t.end());
  for (double ti : t) s.x.push_back(ti / day), s.y.push_back(schedule.at(ti));
  chart.series.push_back(s);
  view["schedule_svg"] = render_svg(chart);
}

std::string time_unit(project::TimeUnit u) {
  return u == project::TimeUnit::d ? "d" : (u == project::TimeUnit::h ? "h" : "s");
}

std::string integration(const project::Numerics& n, bool latent_heat) {
  if (n.integrator == project::IntegratorKind::explicit_euler)
    return fmt::format("explicit (forward Euler), β = {}", number(n.beta, 3));
  const std::string name = n.integrator == project::IntegratorKind::rkl2 ? "RKL2 super-time-stepping"
                                                                         : "implicit (backward Euler)";
  return latent_heat
             ? fmt::format("{}, step: at most {} of the latent heat per particle", name, number(n.step_change, 3))
             : name;
}

// What the SPH heat conduction used: kernel, Laplacian, pair conductivity, symmetry.
void add_sph_numerics(const project::Project& p, json& rows) {
  const auto& n = p.numerics;
  rows.push_back(
      row("kernel", fmt::format("{}, h = {} × spacing",
                                n.kernel == project::KernelKind::cubic_spline ? "cubic spline" : "Wendland C2",
                                number(n.smoothing_ratio, 2))));
  rows.push_back(row("time integration", integration(n, p.soil.latent_heat > 0.0)));
  rows.push_back(
      row("Laplacian", n.laplacian == project::LaplacianForm::renormalised ? "renormalised" : "plain (the paper's)"));
  rows.push_back(row("conductivity between particles", n.conductivity_mean == project::ConductivityMean::harmonic
                                                           ? "harmonic mean"
                                                           : "arithmetic (k_i + k_j)"));
  if (std::holds_alternative<project::ShaftSection>(p.geometry))
    rows.push_back(row("symmetry", n.use_symmetry        ? "smallest mirror wedge"
                                   : n.unsymmetric_cloud ? "none: the full ring, placed without symmetry"
                                                         : "off: full ring"));
}

// What the peridynamics used: horizon, thermal bonds, bond law, solver.
void add_pd_numerics(const RunRecord& run, json& rows) {
  const auto& p = *run.project;
  const json& m = run.summary.value(keys::run, json::object()).value("mechanics", json::object());
  const double spacing =
      run.summary.value(keys::run, json::object()).value(keys::spacing, p.numerics.spacing.value_or(0.0));
  rows.push_back(row("method", "peridynamics (PD), bond-based, on a square lattice"));
  rows.push_back(row("horizon", fmt::format("δ = {} × spacing = {} mm", number(p.numerics.horizon, 3),
                                            number(1e3 * p.numerics.horizon * spacing, 4))));
  rows.push_back(row("heat conduction", "PD thermal bonds within the horizon"));
  rows.push_back(row("time integration (heat)", integration(p.numerics, p.soil.latent_heat > 0.0)));
  if (!p.mechanics) return;
  const auto& mech = *p.mechanics;
  const bool breaks = m.value("critical_stretch", json()).is_number();
  rows.push_back(
      row("bond law",
          breaks ? fmt::format("prototype microelastic brittle: micromodulus {:.4g} N/m⁶, breaks at stretch {:.4g}",
                               m.value("micromodulus", 0.0), m["critical_stretch"].get<double>())
                 : fmt::format("linear elastic, micromodulus {:.4g} N/m⁶; bonds never break (no fracture energy)",
                               m.value("micromodulus", 0.0))));
  rows.push_back(row("kinematics", mech.linear_kinematics ? "linear (stretch linearised in the displacement)"
                                                          : "nonlinear (exact stretch)"));
  rows.push_back(row("equilibrium", mech.equilibrium == project::Mechanics::Equilibrium::direct
                                        ? "direct: sparse Cholesky factor preconditioning conjugate gradients"
                                        : fmt::format("adaptive dynamic relaxation, tolerance {:g}", mech.tolerance)));
  rows.push_back(row("re-equilibrated",
                     mech.temperature_change
                         ? fmt::format("when a particle's temperature moved {} K, and at every snapshot",
                                       number(*mech.temperature_change, 2))
                         : "when a temperature moved 10 % of the largest change so far, and at every snapshot"));
}

void add_numerics(const RunRecord& run, json& view) {
  const auto& p = *run.project;
  const auto& n = p.numerics;
  const auto& facts = run.summary.value(keys::run, json::object());
  const double u = p.time.unit_seconds();
  std::string snapshots;
  for (double t : p.time.snapshots) snapshots += (snapshots.empty() ? "" : ", ") + fmt::format("{:g}", t / u);
  json rows = json::array({
      row("particle spacing", facts.contains(keys::spacing) ? metres(facts.value(keys::spacing, 0.0), 4) + " m" +
                                                                  (n.spacing ? "" : " (chosen by frostwall)")
                                                            : (n.spacing ? number(*n.spacing, 4) + " m" : "default")),
  });
  if (n.method == project::Method::pd) add_pd_numerics(run, rows);
  else add_sph_numerics(p, rows);
  rows.push_back(row("simulated time", fmt::format("{:g} {}", p.time.end / u, time_unit(p.time.unit))));
  rows.push_back(row("snapshots", snapshots + " " + time_unit(p.time.unit)));
  view["numerics_rows"] = rows;
}

// The solid of a PD run: elasticity, expansion, fracture, supports.
void add_solid(const project::Mechanics& m, json& view) {
  auto support = [](const project::Support& s) {
    switch (s.kind) {
      case project::Support::Kind::free: return std::string("free");
      case project::Support::Kind::roller: return std::string("roller");
      case project::Support::Kind::fixed: return std::string("fixed");
      case project::Support::Kind::displacement: return fmt::format("held at ({:g}, {:g}) m", s.ux, s.uy);
    }
    return std::string();
  };
  const auto& mat = m.material;
  view["solid_rows"] = json::array({
      row("elastic modulus", number(mat.elastic_modulus / 1e9, 2) + " GPa"),
      row("Poisson's ratio",
          number(mat.poisson_ratio, 3) + (m.plane == project::Plane::strain ? " (plane strain)" : " (plane stress)")),
      row("thermal expansion",
          fmt::format("{:g} /K, stress-free at {} °C", mat.thermal_expansion, number(mat.reference_temperature, 1))),
      row("fracture energy",
          mat.fracture_energy ? number(*mat.fracture_energy, 2) + " J/m²" : std::string("none: bonds never break")),
      row("supports", fmt::format("left {}, right {}, bottom {}, top {}", support(m.left), support(m.right),
                                  support(m.bottom), support(m.top))),
  });
  view["has_solid_rows"] = true;
}

void add_design_and_sensors(const project::Project& p, json& view) {
  json rows = json::array();
  // A plain geometry has no wall to design: its targets only when given.
  const bool shaft = std::holds_alternative<project::ShaftSection>(p.geometry);
  if (shaft || p.design.required_thickness)
    rows.push_back(row("required wall thickness", p.design.required_thickness
                                                      ? number(*p.design.required_thickness, 2) + " m (weakest ray)"
                                                      : "none"));
  if (shaft || p.design.max_mean_temperature)
    rows.push_back(row("max. mean wall temperature", p.design.max_mean_temperature
                                                         ? number(*p.design.max_mean_temperature, 1) + " °C (on OB)"
                                                         : "none"));
  if (p.design.checks_strength()) {
    std::string where = p.design.depth ? " at " + number(*p.design.depth, 1) + " m depth" : "";
    rows.push_back(
        row("wall check",
            fmt::format("{} with the lateral pressure {} MPa{}, allowable {} of the frozen soil's strength at "
                        "the thinnest wall's mean temperature",
                        project::name(p.design.formula), number(*p.design.pressure, 3), where,
                        number(p.design.allowable_factor, 2))));
  }
  view["design_rows"] = rows;
  view["has_design_rows"] = !rows.empty();
  json sensors = json::array();
  for (const auto& s : p.monitoring)
    sensors.push_back({{"name", s.name},
                       {"x", metres(s.x, 3)},
                       {"y", metres(s.y, 3)},
                       {"r", metres(std::hypot(s.x, s.y), 3)},
                       {"theta", number(std::atan2(s.y, s.x) * 180 / std::numbers::pi, 3)}});
  view["has_sensors"] = !sensors.empty();
  view["sensors"] = sensors;
  view["has_design_or_sensors"] = !rows.empty() || !sensors.empty();
}

}  // namespace

WedgeSymmetry wedge_of(const json& summary) {
  WedgeSymmetry w;
  if (!summary.contains(keys::wedge)) return w;
  const auto& s = summary[keys::wedge];
  w.mirror_lines = s.value("mirror_lines", 0);
  w.start = s.value("start_deg", 0.0) * std::numbers::pi / 180;
  w.angle = s.value("angle_deg", 360.0) * std::numbers::pi / 180;
  return w;
}

void add_project(const RunRecord& run, json& view) {
  // Every key the template names, so nothing renders from a missing value.
  for (const char* key : {"layout_rows", "domain_rows", "soil_rows", "soil_common", "schedule_rows", "numerics_rows",
                          "design_rows", "sensors"})
    view[key] = json::array();
  for (const char* key : {"layout_svg", "layout_caption", "soil_name", "schedule_note"}) view[key] = "";
  view["schedule_svg"] = false;
  view["soil_curve_svg"] = false;
  for (const char* key : {"has_sensors", "has_design_rows", "has_design_or_sensors", "has_solid_rows"})
    view[key] = false;
  view["solid_rows"] = json::array();
  view["soil_heading"] = run.mechanics() || run.frost() ? "Material" : "Soil";
  view["has_project"] = run.project.has_value();
  if (!run.project) return;
  const auto& p = *run.project;

  const bool shaft = std::holds_alternative<project::ShaftSection>(p.geometry);
  json domain = json::array({row(shaft ? "initial ground temperature" : "initial temperature",
                                 number(p.domain.initial_temperature, 1) + " °C")});
  if (const auto* section = std::get_if<project::ShaftSection>(&p.geometry)) {
    add_layout(run, *section, view);
    domain.push_back(
        row("far field", (p.domain.far_field_temperature ? number(*p.domain.far_field_temperature, 1) + " °C"
                                                         : std::string("adiabatic")) +
                             " at r = " + number(section->outer_radius, 1) + " m"));
    add_schedule(p, section->pipe.temperature, view);
  } else {
    const auto& r = std::get<project::Rectangle>(p.geometry);
    view["layout_svg"] = rectangle_svg(r);
    view["layout_caption"] = "Plain geometry: the rectangle and its boundary conditions.";
    view["layout_rows"] = json::array({row("geometry", fmt::format("rectangle {:g} m × {:g} m", r.width, r.height))});
    view["schedule_note"] = "";
    if (p.mechanics) add_solid(*p.mechanics, view);
  }
  view["domain_rows"] = domain;
  add_soil(p.soil, view);
  add_numerics(run, view);
  add_design_and_sensors(p, view);
}

}  // namespace frostwall::report::detail
