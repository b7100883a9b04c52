// The blocks of a "physics": "cfd-dem" project (README, project-file
// fields). LAMMPS aborts the process on a bad command, so every value that
// reaches a command is checked here first.
#include "project/load_cfd_dem.hpp"

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <set>

#include "project/load_reports.hpp"

namespace frostwall::project {

const char* face_name(BoxFace f) {
  static const char* names[] = {"x_min", "x_max", "y_min", "y_max", "z_min", "z_max"};
  return names[static_cast<int>(f)];
}

int gravity_axis(const CfdDem& c) {
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(c.gravity[k]) > std::abs(c.gravity[axis])) axis = k;
  return c.gravity[axis] == 0.0 ? -1 : axis;
}

double FlowSettings::velocity_at(double t) const {
  if (darcy_velocity.empty()) return 0.0;
  if (t <= darcy_velocity.front().first) return darcy_velocity.front().second;
  for (std::size_t k = 1; k < darcy_velocity.size(); ++k) {
    const auto [t1, u1] = darcy_velocity[k];
    if (t <= t1) {
      const auto [t0, u0] = darcy_velocity[k - 1];
      return t1 > t0 ? u0 + (u1 - u0) * (t - t0) / (t1 - t0) : u1;
    }
  }
  return darcy_velocity.back().second;
}

double rayleigh_time(const GrainSettings& g) {
  const double shear = g.youngs_modulus / (2.0 * (1.0 + g.poisson_ratio));
  return std::numbers::pi * 0.5 * g.diameter_min * std::sqrt(g.density / shear) / (0.1631 * g.poisson_ratio + 0.8766);
}

namespace detail {

namespace {

std::optional<Point3> read_point3(const Node& n) {
  if (!n.given()) return std::nullopt;
  const Json& j = n.json();
  if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number()) {
    n.problem("must be a point [x, y, z] in metres, got " + n.shown());
    return std::nullopt;
  }
  return Point3{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

bool inside(const Point3& p, const Point3& low, const Point3& high) {
  for (int k = 0; k < 3; ++k)
    if (p[k] < low[k] || p[k] > high[k]) return false;
  return true;
}

std::optional<BoxFace> read_face(const Node& n) {
  return n.choice<BoxFace>("face", {{"x_min", BoxFace::x_min},
                                    {"x_max", BoxFace::x_max},
                                    {"y_min", BoxFace::y_min},
                                    {"y_max", BoxFace::y_max},
                                    {"z_min", BoxFace::z_min},
                                    {"z_max", BoxFace::z_max}});
}

CfdDemBox read_box(const Node& n) {
  CfdDemBox box;
  if (!n.object({"low", "high", "periodic"})) return box;
  const auto low = read_point3(n["low"].required()), high = read_point3(n["high"].required());
  if (low && high) {
    box.low = *low;
    box.high = *high;
    for (int k = 0; k < 3; ++k)
      if (!(high->at(k) > low->at(k)))
        n["high"].problem(fmt::format("must be above box.low on every axis, got {} <= {} on axis {}", high->at(k),
                                      low->at(k), "xyz"[k]));
  }
  if (const Node p = n["periodic"]; p.present()) {
    const Json& j = p.json();
    if (!j.is_array() || j.size() != 3 || !j[0].is_boolean() || !j[1].is_boolean() || !j[2].is_boolean())
      p.problem("must be [true|false, true|false, true|false] (x, y, z), got " + p.shown());
    else
      for (int k = 0; k < 3; ++k) box.periodic[k] = j[k].get<bool>();
  }
  return box;
}

GrainSettings read_grains(const Node& n, const CfdDemBox& box) {
  GrainSettings g;
  if (!n.object({"diameter", "diameter_range", "density", "youngs_modulus", "poisson_ratio", "restitution", "friction",
                 "rolling_friction", "count", "porosity", "fill", "seed", "settle_time", "held", "settle_friction"}))
    return g;
  const Node d = n["diameter"], range = n["diameter_range"];
  if (d.present() == range.present()) d.problem(R"(give either "diameter" (m) or "diameter_range" [min, max] (m))");
  if (const auto v = d.positive()) g.diameter_min = g.diameter_max = *v;
  if (range.present()) {
    const Json& j = range.json();
    if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number() || !(j[0].get<double>() > 0) ||
        j[1].get<double>() < j[0].get<double>())
      range.problem("must be [min, max] in metres with 0 < min <= max, got " + range.shown());
    else g.diameter_min = j[0].get<double>(), g.diameter_max = j[1].get<double>();
  }
  g.density = n["density"].required().positive().value_or(g.density);
  g.youngs_modulus = n["youngs_modulus"].positive().value_or(g.youngs_modulus);
  if (const auto v = n["poisson_ratio"].number()) {
    if (*v <= -1.0 || *v >= 0.5) n["poisson_ratio"].problem(fmt::format("must be above -1 and below 0.5, got {}", *v));
    else g.poisson_ratio = *v;
  }
  if (const auto v = n["restitution"].number()) {
    if (*v <= 0.0 || *v > 1.0) n["restitution"].problem(fmt::format("must be above 0 and at most 1, got {}", *v));
    else g.restitution = *v;
  }
  g.friction = n["friction"].non_negative().value_or(g.friction);
  g.settle_friction = n["settle_friction"].non_negative();
  g.rolling_friction = n["rolling_friction"].non_negative().value_or(g.rolling_friction);
  const Node count = n["count"], porosity = n["porosity"];
  if (count.present() == porosity.present())
    count.problem(R"(give either "count" (grains) or "porosity" (of the fill region))");
  if (const auto c = count.count()) g.count = *c;
  if (const auto e = porosity.number()) {
    // Below 0.26 no packing of spheres exists; 1 has no grains.
    if (*e < 0.26 || *e >= 1.0) porosity.problem(fmt::format("must be at least 0.26 and below 1, got {}", *e));
    else g.porosity = *e;
  }
  g.fill_low = box.low;
  g.fill_high = box.high;
  if (const Node fill = n["fill"]; fill.object({"low", "high"})) {
    const auto low = read_point3(fill["low"].required()), high = read_point3(fill["high"].required());
    if (low && high) {
      // Above the box (against gravity, z here) it may go: a settling column.
      Point3 roof = box.high;
      roof[2] = std::max(roof[2], high->at(2));
      if (!inside(*low, box.low, box.high) || !inside(*high, box.low, roof))
        fill.problem("must lie inside the box (it may reach above its top: a settling column)");
      else {
        bool ordered = true;
        for (int k = 0; k < 3; ++k) ordered = ordered && high->at(k) > low->at(k);
        if (!ordered) fill["high"].problem("must be above fill.low on every axis");
        g.fill_low = *low, g.fill_high = *high;
      }
    }
  }
  if (const auto s = n["seed"].number()) {
    if (*s < 0 || *s != std::floor(*s) || *s > 9e15)
      n["seed"].problem(fmt::format("must be a whole number >= 0, got {}", *s));
    else g.seed = static_cast<unsigned long long>(*s);
  }
  g.settle_time = n["settle_time"].non_negative().value_or(0.0);
  g.held = n["held"].boolean().value_or(false);
  if (g.diameter_max > 0)
    for (int k = 0; k < 3; ++k)
      if (g.fill_high[k] - g.fill_low[k] < g.diameter_max)
        n["diameter"].problem(fmt::format("the largest grain ({} m) does not fit across the fill region along {}",
                                          g.diameter_max, "xyz"[k]));
  return g;
}

FluidSettings read_fluid(const Node& n, const CfdDemBox& box) {
  FluidSettings f;
  if (!n.object({"density", "viscosity", "cell_size", "cells", "min_porosity"})) return f;
  f.density = n["density"].required().positive().value_or(f.density);
  f.viscosity = n["viscosity"].required().positive().value_or(f.viscosity);
  const Node size = n["cell_size"], cells = n["cells"];
  if (size.present() == cells.present()) size.problem(R"(give either "cell_size" (m) or "cells" [nx, ny, nz])");
  if (const auto h = size.positive()) {
    for (int k = 0; k < 3; ++k)
      if (const double side = box.high[k] - box.low[k]; side > 0 && *h > side * (1 + 1e-9)) {
        size.problem(
            fmt::format("{} m is larger than the box along {} ({} m); use at most {} m", *h, "xyz"[k], side,
                        std::min({box.high[0] - box.low[0], box.high[1] - box.low[1], box.high[2] - box.low[2]})));
        return f;
      }
    for (int k = 0; k < 3; ++k) {
      const double n_k = (box.high[k] - box.low[k]) / *h;
      if (n_k > 1e6) {
        size.problem(fmt::format("{} m gives more than a million cells along {}", *h, "xyz"[k]));
        return f;
      }
      f.cells[k] = std::max(1, static_cast<int>(std::lround(n_k)));
    }
  }
  if (cells.present()) {
    const Json& j = cells.json();
    bool ok = j.is_array() && j.size() == 3;
    for (std::size_t k = 0; ok && k < 3; ++k)
      ok = j[k].is_number_integer() && j[k].get<long>() >= 1 && j[k].get<long>() <= 1000000;
    if (!ok) cells.problem("must be [nx, ny, nz], whole numbers from 1 to 1e6, got " + cells.shown());
    else
      for (int k = 0; k < 3; ++k) f.cells[k] = j[k].get<int>();
    f.cells_given = true;
  }
  if (const auto e = n["min_porosity"].number()) {
    if (*e <= 0.0 || *e >= 1.0) n["min_porosity"].problem(fmt::format("must be above 0 and below 1, got {}", *e));
    else f.min_porosity = *e;
  }
  return f;
}

FlowSettings read_flow(const Node& n) {
  FlowSettings flow;
  if (!n.object({"inflow", "darcy_velocity", "inflow_pressure", "outflow", "outflow_pressure", "open_to_grains"}))
    return flow;
  flow.open_to_grains = n["open_to_grains"].boolean().value_or(false);
  flow.inflow = read_face(n["inflow"].required()).value_or(flow.inflow);
  flow.outflow = read_face(n["outflow"].required()).value_or(flow.outflow);
  if (n["inflow"].present() && n["outflow"].present() && flow.inflow == flow.outflow)
    n["outflow"].problem("must be another face than flow.inflow");
  const Node u = n["darcy_velocity"], p = n["inflow_pressure"];
  if (u.present() == p.present())
    u.problem(R"(give either "darcy_velocity" (m/s, or [[s, m/s], ...]) or "inflow_pressure" (Pa))");
  flow.inflow_pressure = p.number();
  flow.outflow_pressure = n["outflow_pressure"].number().value_or(0.0);
  if (u.present()) {
    if (u.json().is_number()) flow.darcy_velocity = {{0.0, u.json().get<double>()}};
    else if (!u.json().is_array() || u.json().empty())
      u.problem("must be a number (m/s) or a [[s, m/s], ...] schedule, got " + u.shown());
    else
      for (std::size_t i = 0; i < u.json().size(); ++i) {
        const Json& q = u.json()[i];
        if (!q.is_array() || q.size() != 2 || !q[0].is_number() || !q[1].is_number()) {
          u[i].problem("must be a point [s, m/s], got " + u[i].shown());
          continue;
        }
        const double t = q[0].get<double>();
        if (t < 0 || (!flow.darcy_velocity.empty() && t <= flow.darcy_velocity.back().first)) {
          u[i][0].problem(fmt::format("times must be >= 0 and ascending, got {}", t));
          continue;
        }
        flow.darcy_velocity.emplace_back(t, q[1].get<double>());
      }
  }
  return flow;
}

std::vector<std::string> read_forces(const Node& n) {
  if (!n.present()) return default_fluid_forces;
  std::vector<std::string> forces;
  const auto size = n.array();
  std::set<std::string> seen;
  int drags = 0;
  for (std::size_t i = 0; i < size.value_or(0); ++i) {
    const auto name = n[i].choice<std::string>("fluid force", {{"difelice_drag", "difelice_drag"},
                                                               {"gidaspow_drag", "gidaspow_drag"},
                                                               {"schiller_naumann_drag", "schiller_naumann_drag"},
                                                               {"pressure_gradient", "pressure_gradient"},
                                                               {"buoyancy", "buoyancy"}});
    if (!name) continue;
    if (!seen.insert(*name).second) n[i].problem("'" + *name + "' is listed twice");
    if (name->ends_with("_drag") && ++drags > 1) n[i].problem("only one drag law at a time");
    forces.push_back(*name);
  }
  return forces;
}

// x to two significant digits, rounded down (or up): a suggested limit that passes.
double two_digits(double x, bool up) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1);
  return (up ? std::ceil(x / unit - 1e-9) : std::floor(x / unit + 1e-9)) * unit;
}

bool positive_number(const Node& n) { return n.present() && n.json().is_number() && n.json().get<double>() > 0; }

// What LAMMPS and the coupling cannot run, though every value is in range
// alone: grains that float, a cavity out of the box, a DEM step past half
// the Rayleigh time ("Lost atoms"), bins far below a grain ("Too many
// neighbor bins").
void check_cfd_dem_limits(const Node& root, const CfdDem& c) {
  const Node grains = root["grains"], density = grains["density"];
  if (positive_number(density) && positive_number(root["fluid"]["density"]) && !(c.grains.density > c.fluid.density))
    density.problem(fmt::format("{} kg/m3 is not above fluid.density ({} kg/m3): the grains would not settle",
                                c.grains.density, c.fluid.density));
  if (const Node cav = root["cavity"];
      c.cavity && c.cavity->radius > 0 && inside(c.cavity->centre, c.box.low, c.box.high))
    for (int k = 0; k < 3; ++k)
      if (c.cavity->centre[k] - c.cavity->radius < c.box.low[k] ||
          c.cavity->centre[k] + c.cavity->radius > c.box.high[k]) {
        const auto& x = c.cavity->centre;
        cav["radius"].problem(
            fmt::format("the cavity ({} m round ({}, {}, {})) does not fit in the box ({} to {} m along {})",
                        c.cavity->radius, x[0], x[1], x[2], c.box.low[k], c.box.high[k], "xyz"[k]));
        break;
      }
  if (!(c.grains.diameter_min > 0) || !positive_number(density)) return;
  const double rayleigh = rayleigh_time(c.grains);
  if (const auto dt = c.coupling.dem_timestep; dt && *dt > max_rayleigh_fraction * rayleigh * (1 + 1e-9))
    root["coupling"]["dem_timestep"].problem(fmt::format(
        "{:.3g} s is more than {} of the smallest grain's Rayleigh time ({:.3g} s): the grains would fly apart; use {:.2g} s or less",
        *dt, max_rayleigh_fraction, rayleigh, two_digits(max_rayleigh_fraction * rayleigh, false)));
  if (const auto bin = c.neighbour.bin_size; bin && *bin < min_bin_fraction * c.grains.diameter_min)
    root["neighbour"]["bin_size"].problem(fmt::format(
        "{:.3g} m is less than {} of the smallest grain's diameter ({} m): far too many bins; use {:.2g} m or more",
        *bin, min_bin_fraction, c.grains.diameter_min, two_digits(min_bin_fraction * c.grains.diameter_min, true)));
}

}  // namespace

void read_cfd_dem(const Node& root, Project& project) {
  root.object({"name", "description", "physics", "grains", "box", "cavity", "fluid", "flow", "gravity", "forces",
               "coupling", "neighbour", "time", "output", "max_grains", "point_a", "heap"});
  project.name = root["name"].required().string().value_or("");
  project.description = root["description"].string(true).value_or("");
  CfdDem c;
  c.box = read_box(root["box"].required());
  c.grains = read_grains(root["grains"].required(), c.box);
  if (const Node cav = root["cavity"]; cav.object({"centre", "radius", "drain"})) {
    Cavity cavity;
    if (const auto centre = read_point3(cav["centre"].required())) cavity.centre = *centre;
    cavity.radius = cav["radius"].required().positive().value_or(0.0);
    cavity.drain = cav["drain"].boolean().value_or(false);
    if (!inside(cavity.centre, c.box.low, c.box.high)) cav["centre"].problem("must lie inside the box");
    c.cavity = cavity;
  }
  c.fluid = read_fluid(root["fluid"].required(), c.box);
  if (const Node flow = root["flow"]; flow.present()) c.flow = read_flow(flow);
  if (const Node g = root["gravity"]; g.present())
    if (const auto v = read_point3(g)) c.gravity = *v;
  c.forces = read_forces(root["forces"]);
  if (const Node heap = root["heap"]; heap.object({"axis", "lift_speed"})) {
    Heap h{
        {0.5 * (c.grains.fill_low[0] + c.grains.fill_high[0]), 0.5 * (c.grains.fill_low[1] + c.grains.fill_high[1])}};
    if (const Node axis = heap["axis"]; axis.present()) {
      const auto& j = axis.json();
      if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) axis.problem("must be [x, y] in m");
      else h.axis = {j[0].get<double>(), j[1].get<double>()};
    }
    if (!(h.axis[0] > c.box.low[0] && h.axis[0] < c.box.high[0] && h.axis[1] > c.box.low[1] &&
          h.axis[1] < c.box.high[1]))
      (heap["axis"].present() ? heap["axis"] : heap).problem("must lie inside the box (x and y)");
    h.lift_speed = heap["lift_speed"].positive().value_or(h.lift_speed);
    if (c.grains.settle_time <= 0.0)
      root["grains"]["settle_time"].problem("a heap settles in its container first: give a settle time");
    if (!(c.gravity[2] < 0.0 && c.gravity[0] == 0.0 && c.gravity[1] == 0.0))
      heap.problem("a heap needs gravity along -z");
    c.heap = h;
  }
  if (const Node cp = root["coupling"]; cp.object({"interval", "dem_timestep", "drag"})) {
    if (const auto k = cp["interval"].count()) c.coupling.interval = *k;
    c.coupling.dem_timestep = cp["dem_timestep"].positive();
    c.coupling.drag = cp["drag"]
                          .choice<DragCoupling>("drag coupling", {{"semi_implicit", DragCoupling::semi_implicit},
                                                                  {"explicit", DragCoupling::explicit_force}})
                          .value_or(c.coupling.drag);
  }
  if (const Node nb = root["neighbour"]; nb.object({"skin", "every", "bin_size"})) {
    c.neighbour.skin = nb["skin"].positive();
    if (c.neighbour.skin && *c.neighbour.skin > c.grains.diameter_max)
      nb["skin"].problem(
          "must not exceed the largest grain's diameter (each grain would list far more than its contacts)");
    if (const auto k = nb["every"].count()) {
      c.neighbour.every = *k;
      if (*k > 100) nb["every"].problem("must be at most 100 steps");
    }
    c.neighbour.bin_size = nb["bin_size"].positive();
  }
  c.max_grains = root["max_grains"].positive();
  if (const Node a = root["point_a"]; a.present()) {
    if (const auto x = read_point3(a)) {
      if (!inside(*x, c.box.low, c.box.high)) a.problem("must lie inside the box");
      c.point_a = *x;
    }
  } else if (c.cavity) {
    c.point_a = Point3{c.cavity->centre[0], c.cavity->centre[1], c.box.high[2] - 0.04};
  }
  // A settling column above the box needs gravity down z.
  if (c.grains.fill_high[2] > c.box.high[2] && !(c.gravity[2] < 0.0 && c.gravity[0] == 0.0 && c.gravity[1] == 0.0))
    root["grains"]["fill"]["high"].problem("reaches above the box: a settling column needs gravity along -z");
  // A periodic axis carries no flow through its faces.
  if (c.flow)
    for (const auto& [face, key] : {std::pair{c.flow->inflow, "inflow"}, std::pair{c.flow->outflow, "outflow"}})
      if (c.box.periodic[static_cast<int>(face) / 2])
        root["flow"][key].problem(fmt::format("'{}' lies on a periodic axis of box.periodic", face_name(face)));
  check_cfd_dem_limits(root, c);
  project.time = read_time(root["time"].required());
  project.output = read_output(root["output"].required());
  project.cfd_dem = std::move(c);
}

}  // namespace detail

}  // namespace frostwall::project
