#include "run/run_project.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include "run/cfd_dem_run.hpp"
#include "post/frozen_area_trend.hpp"
#include "post/gap_closure.hpp"
#include "run/closure_tracker.hpp"
#include "run/model.hpp"
#include "thermal/backward_euler.hpp"
#include "thermal/super_time_stepping.hpp"
#include "run/frost_results.hpp"
#include "run/groundwater_flow.hpp"
#include "run/mechanics_run.hpp"
#include "run/plain_results.hpp"
#include "run/brine_log.hpp"
#include "run/shaft_results.hpp"
#include "particles/symmetry_group.hpp"
#include "io/atomic_file.hpp"
#include "io/point_cloud_vtk.hpp"
#include "post/front.hpp"
#include "report/report.hpp"
#include "thermal/thermal_model.hpp"
#include "thermal/time_loop.hpp"

namespace frostwall::run {

namespace fs = std::filesystem;
using project::Project;

namespace {

// Output times: the snapshots, plus a regular series for the time curves.
std::vector<double> sample_times(const project::TimeSettings& time, std::size_t regular) {
  std::vector<double> t = time.snapshots;
  for (std::size_t k = 1; k <= regular; ++k) t.push_back(time.end * k / regular);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [&](double a, double b) { return std::abs(a - b) <= 1e-12 * time.end; }),
          t.end());
  return t;
}

// Snapshot files are named by their time in the project's unit when those
// are whole numbers (field_0010.vtu for day 10), else by their number.
std::vector<std::string> snapshot_stems(const project::TimeSettings& time, const std::string& prefix) {
  const double u = time.unit_seconds();
  bool whole = true;
  for (double t : time.snapshots) whole = whole && std::abs(t / u - std::round(t / u)) < 1e-9;
  std::vector<std::string> stems;
  for (std::size_t k = 0; k < time.snapshots.size(); ++k)
    stems.push_back(fmt::format("{}_{:04d}", prefix, whole ? std::lround(time.snapshots[k] / u) : long(k + 1)));
  return stems;
}

io::PointCloudFrame frame_of(const particles::ParticleSet<2>& particles, const thermal::ThermalModel& model) {
  io::PointCloudFrame frame;
  const std::size_t n = particles.size();
  frame.points.reserve(n);
  for (const auto& x : particles.position) frame.points.push_back({x[0], x[1], 0.0});
  std::vector<double> phase(n), k(n), boundary(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double f = model.liquid_fraction()[i];
    phase[i] = f <= 0.0 ? -1.0 : (f >= 1.0 ? 1.0 : 0.0);  // the paper's flag: -1 frozen, 0 freezing, +1 unfrozen
    k[i] = 0.5 * (model.conductivity(i, 0) + model.conductivity(i, 1));
    boundary[i] = particles.boundary[i];
  }
  frame.fields = {{"temperature", model.temperature()}, {"enthalpy", model.enthalpy()},
                  {"liquid_fraction", model.liquid_fraction()}, {"phase", phase},
                  {"conductivity", k}, {"volume", particles.volume}, {"boundary", boundary}};
  return frame;
}

// The solid's displacement (a vector) and damage; the thermal layers beyond
// held faces are not solid: 0 there.
void add_mechanics(io::PointCloudFrame& frame, const MechanicsRun& mechanics) {
  const auto& u = mechanics.displacement();
  const auto damage = mechanics.damage();
  std::vector<double> vectors(3 * frame.points.size(), 0.0), phi(frame.points.size(), 0.0);
  for (std::size_t i = 0; i < damage.size(); ++i) {
    vectors[3 * i] = u[2 * i];
    vectors[3 * i + 1] = u[2 * i + 1];
    phi[i] = damage[i];
  }
  frame.vectors.emplace_back("displacement", std::move(vectors));
  frame.fields.emplace_back("damage", std::move(phi));
  const auto sigma = mechanics.stress();
  const char* names[3] = {"stress_xx", "stress_yy", "stress_xy"};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> component(frame.points.size(), 0.0);
    for (std::size_t i = 0; i < sigma.size(); ++i) component[i] = sigma[i][c];
    frame.fields.emplace_back(names[c], std::move(component));
  }
}

// The whole ring for ParaView: every copy of the wedge under its mirror group.
io::PointCloudFrame full_ring(const io::PointCloudFrame& wedge, const std::vector<particles::MirrorPlane<2>>& mirrors,
                              double length_scale) {
  const auto group = particles::symmetry_group(mirrors, length_scale);
  io::PointCloudFrame ring;
  ring.single_precision = true;  // 50x the wedge's particles: float32 halves the file and its write time
  for (const auto& field : wedge.fields)
    if (field.first == "temperature" || field.first == "liquid_fraction" || field.first == "phase")
      ring.fields.push_back(field);
  for (auto& field : ring.fields) field.second.clear();
  for (const auto& g : group) {
    for (const auto& x : wedge.points) {
      const particles::Vec<2> y = g(particles::Vec<2>(x[0], x[1]));
      ring.points.push_back({y[0], y[1], 0.0});
    }
    for (auto& field : ring.fields)
      for (const auto& source : wedge.fields)
        if (source.first == field.first) field.second.insert(field.second.end(), source.second.begin(), source.second.end());
  }
  return ring;
}

const char* integrator_name(project::IntegratorKind k) {
  if (k == project::IntegratorKind::rkl2) return "rkl2";
  return k == project::IntegratorKind::implicit ? "implicit" : "explicit";
}

}  // namespace

void check_output_directory(const std::string& directory) {
  // The nearest ancestor that exists must be a directory we may write in;
  // nothing is created here (bad input writes nothing).
  std::error_code ec;
  fs::path existing = fs::absolute(fs::path(directory).lexically_normal(), ec);
  while (!existing.empty() && !fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  const char* reason = nullptr;
  if (!fs::is_directory(existing, ec)) reason = std::strerror(ENOTDIR);
  else if (access(existing.c_str(), W_OK | X_OK) != 0) reason = std::strerror(errno);
  if (reason) throw project::ProjectError({fmt::format("output.directory: cannot create '{}': {}", directory, reason)});
}

void run_project(const Project& p, const RunOptions& options) {
  if (p.cfd_dem) return run_cfd_dem(p, options);
  // The regional flow is held on the far field: an adiabatic one has none.
  if (p.groundwater && !p.domain.far_field_temperature)
    throw project::ProjectError({"groundwater: needs domain.far_field_temperature (the far field holds the regional flow "
                                 "and the temperature of the water that enters)"});
  const auto wall_start = std::chrono::steady_clock::now();
  auto note = [&](const std::string& s) {
    if (options.note) options.note(s);
  };
  check_output_directory(p.output.directory);
  if (!p.layers.empty())  // study::run_layers runs them, one project per layer
    throw project::ProjectError({"layers: a layered project runs with `frostwall run`, one cross-section per layer"});
  Model built = build_model(p);
  for (const auto& n : built.scene->notes) note(n);
  const auto& particles = built.particles();
  const auto& face = built.face;
  thermal::ThermalModel& model = *built.model;
  const std::size_t pair_count = model.pairs().pairs();
  const double h = built.h;
  const double unit = p.time.unit_seconds();

  // ---- output
  const fs::path out = p.output.directory;
  fs::create_directories(out);
  if (!options.project_text.empty()) io::write_text_file(out / "project.json", options.project_text);
  const auto stems = snapshot_stems(p.time, "field");
  std::vector<io::PvdEntry> pvd, ring_pvd;
  const bool write_ring = p.output.vtk && p.output.full_ring && built.shaft && !particles.mirrors.empty();
  nlohmann::json front = nlohmann::json::array();
  // Shaft sections: the regular series is read from the fields interpolated
  // linearly in time between the two steps around each sample, so only the
  // snapshots cut a step short (landing on all 200 cost RKL2 12 % more rate
  // evaluations on the single ring). Plain geometries sample at step ends.
  const std::vector<double> series = sample_times(p.time, time_series_points);
  // No RKL2 step longer than that interval: on the single ring, longer late
  // steps (a front particle then freezes within one step) cost 0.5-1 cm of
  // wall thickness.
  const double longest_step = p.time.end / time_series_points;
  if (auto* rkl2 = dynamic_cast<thermal::SuperTimeStepping*>(built.integrator.get())) rkl2->limit_step(longest_step);
  // Flowing groundwater: the conduction integrator wrapped with the flow
  // and the heat it carries.
  GroundwaterFlow* flow = nullptr;
  std::optional<post::GapClosure> gaps;  // under seepage: closure per gap
  post::FrozenAreaTrend frozen_area;      // and whether an open wall still grows
  std::vector<double> latent_left;
  int flow_observed = 0;
  if (p.groundwater) {
    gaps.emplace(built.particles(), geometry::pipe_positions(std::get<project::ShaftSection>(p.geometry).layout));
    auto wrapped = std::make_unique<GroundwaterFlow>(*p.groundwater, built);
    flow = wrapped.get();
    built.integrator = std::move(wrapped);
    gaps->observe_flow(0.0, built.particles(), model.pairs(), flow->pair_flux());
    flow_observed = flow->flow_solves();
  }
  // Closure of a shaft section (a fully frozen path) and the day the frozen
  // columns touch: checked 2000 times over the run while the gap is open,
  // at every step once it freezes.
  std::optional<ClosureTracker> closure;
  if (built.shaft) closure.emplace(built, p.time.end, longest_step);
  const std::vector<double> times = built.shaft ? sample_times(p.time, 0) : series;
  std::unique_ptr<ShaftResults> results;
  std::unique_ptr<PlainResults> plain;
  if (built.shaft) results = std::make_unique<ShaftResults>(p, built);
  else plain = std::make_unique<PlainResults>(p, built);
  std::unique_ptr<MechanicsRun> mechanics;
  if (p.mechanics) {
    mechanics = std::make_unique<MechanicsRun>(p, built);
    plain->attach(mechanics.get());
  }
  std::unique_ptr<FrostResults> frost;
  if (!built.pore_of.empty()) {
    frost = std::make_unique<FrostResults>(p, built, mechanics.get());
    if (mechanics) mechanics->after_equilibrium = [&](double t) { frost->after_equilibrium(t); };
  }
  const double heat_before = model.stored_heat();
  std::unique_ptr<BrineLog> brine;
  if (built.shaft && built.model->boundaries()[built.shaft->pipe_boundary].film)
    brine = std::make_unique<BrineLog>(std::get<project::ShaftSection>(p.geometry).pipe, model, built.shaft->pipe_boundary, series);

  thermal::TimeLoopObservers observers;
  observers.progress = options.progress;
  std::size_t next_sample = 0;
  double t_before = 0.0;
  std::vector<double> f_before, T_before, f_at, T_at;
  observers.after_step = [&](const thermal::ThermalModel& m, double t) {
    if (closure) closure->after_step(m, t);
    if (gaps) {
      m.latent_left(latent_left);
      gaps->observe(t, latent_left);
      if (flow->flow_solves() != flow_observed) {  // the water through each gap, at every new flow
        gaps->observe_flow(t, built.particles(), m.pairs(), flow->pair_flux());
        flow_observed = flow->flow_solves();
      }
      double area = 0.0;
      for (std::size_t i = 0; i < m.free_count(); ++i) area += m.volume()[i] * (1.0 - m.liquid_fraction()[i]);
      frozen_area.add(t / 86400.0, area);
    }
    if (frost) frost->after_step(m, t);
    if (brine) brine->after_step(m, t);
    if (mechanics) mechanics->update(m, t, false);
    if (!results) return;
    const auto& f = m.liquid_fraction();
    const auto& T = m.temperature();
    for (; next_sample < series.size() && series[next_sample] <= t + 1e-12 * p.time.end; ++next_sample) {
      const double tau = series[next_sample];
      const double w = t > t_before ? std::clamp((tau - t_before) / (t - t_before), 0.0, 1.0) : 1.0;
      if (w >= 1.0 || f_before.empty()) {
        results->sample(tau, f, T);
        continue;
      }
      f_at.resize(f.size());
      T_at.resize(T.size());
      for (std::size_t i = 0; i < f.size(); ++i) {
        f_at[i] = f_before[i] + w * (f[i] - f_before[i]);
        T_at[i] = T_before[i] + w * (T[i] - T_before[i]);
      }
      results->sample(tau, f_at, T_at);
    }
    f_before.assign(f.begin(), f.end());
    T_before.assign(T.begin(), T.end());
    t_before = t;
  };
  observers.snapshot = [&](const thermal::ThermalModel& m, double t, std::size_t) {
    if (face) {
      const auto x = post::frozen_front(particles.position, m.liquid_fraction(), m.free_count(), *face);
      front.push_back({t / unit, x ? nlohmann::json(*x) : nlohmann::json(nullptr)});
    }
    const auto k = std::lower_bound(p.time.snapshots.begin(), p.time.snapshots.end(), t - 1e-12 * p.time.end) -
                   p.time.snapshots.begin();
    const bool is_snapshot = k < static_cast<long>(stems.size()) && std::abs(p.time.snapshots[k] - t) <= 1e-12 * p.time.end;
    if (results && is_snapshot) results->snapshot(t, m, out, stems[k]);
    if (mechanics) mechanics->update(m, t, is_snapshot);
    if (plain) plain->sample(t, m);
    if (plain && is_snapshot) plain->snapshot(t, m, out, stems[k]);
    if (frost && is_snapshot) frost->snapshot(t, out, stems[k]);
    if (p.output.vtk && is_snapshot) {
      auto frame = frame_of(particles, m);
      if (mechanics) add_mechanics(frame, *mechanics);
      if (frost) frost->add_fields(frame, m);
      if (flow) flow->add_fields(frame, m);
      io::write_vtu(out / (stems[k] + ".vtu"), frame);
      pvd.push_back({t / unit, stems[k] + ".vtu"});
      if (write_ring) {
        const std::string ring_file = "ring" + stems[k].substr(5) + ".vtu";
        io::write_vtu(out / ring_file, full_ring(frame, particles.mirrors, built.shaft->far_field_radius));
        ring_pvd.push_back({t / unit, ring_file});
      }
    }
  };
  const thermal::TimeLoopResult loop = thermal::run_time_loop(model, *built.integrator, p.time.end, times, observers);
  if (p.output.vtk) io::write_pvd(out / "field.pvd", pvd);
  if (write_ring) io::write_pvd(out / "ring.pvd", ring_pvd);

  // ---- summary
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  nlohmann::json boundary_heat = nlohmann::json::object();
  for (std::size_t b = 0; b < model.boundaries().size(); ++b)
    boundary_heat[model.boundaries()[b].name] = loop.boundary_heat[b];
  // ordered_json: the keys stay in the contract's order.
  nlohmann::ordered_json summary = {{"project", p.name}, {"frostwall_version", FROSTWALL_VERSION}};
  if (built.shaft) {
    const auto closure_time = closure->closure_time();
    const auto contact_time = closure->contact_time();
    summary["closure_time_days"] = closure_time ? nlohmann::json(*closure_time / 86400.0) : nlohmann::json(nullptr);
    summary["front_contact_days"] = contact_time ? nlohmann::json(*contact_time / 86400.0) : nlohmann::json(nullptr);
    const nlohmann::json parts = results->finish(out);
    for (const char* key : {"wall", "design", "monitoring", "interface"})
      if (parts.contains(key)) summary[key] = parts[key];
    if (brine) summary["brine"] = brine->finish(out);
    const auto& w = built.shaft->wedge;
    summary["wedge"] = {{"mirror_lines", w.mirror_count}, {"start_deg", w.start_angle * 180 / M_PI}, {"angle_deg", w.angle * 180 / M_PI}};
  } else {
    summary["front"] = front;
    summary["front_axis"] = face ? nlohmann::json{{"face", face->side}} : nlohmann::json(nullptr);
    const nlohmann::json parts = plain->finish(out);
    for (const char* key : {"front_along", "monitoring", "monitoring_solid", "interface"})
      if (parts.contains(key)) summary[key] = parts[key];
    if (frost) {
      const nlohmann::json pores = frost->finish(out);
      for (const auto& [key, value] : pores.items()) summary[key] = value;
    }
  }
  summary.update(nlohmann::ordered_json{
      {"heat_balance",
       {{"stored_change", model.stored_heat() - heat_before}, {"from_boundaries", boundary_heat}, {"unit", "J/m"}}},
      {"run",
       {{"particles", model.free_count()},
        {"boundary_particles", model.size() - model.free_count()},
        {"pairs", pair_count},
        {"steps", loop.steps},
        {"wall_seconds", wall_seconds},
        {"threads", omp_get_max_threads()},
        {"integrator", integrator_name(p.numerics.integrator)},
        {"method", p.numerics.method == project::Method::pd ? "pd" : "sph"},
        {"spacing", particles.spacing},
        {"placement", particles.graded() ? "graded" : "lattice"},
        {"coarsest_spacing", particles.coarsest_spacing()},
        {"smoothing_length", h},
        {"kernel", built.kernel->name()},
        {"time_unit", p.time.unit == project::TimeUnit::s ? "s" : (p.time.unit == project::TimeUnit::h ? "h" : "d")}}},
      {"warnings", p.warnings},
  });
  if (const auto* implicit = thermal::find_integrator<thermal::BackwardEuler>(built.integrator.get())) {
    const auto& stats = implicit->statistics();
    summary["run"]["newton_iterations"] = stats.newton_iterations;
    summary["run"]["linear_iterations"] = stats.linear_iterations;
    summary["run"]["step_halvings"] = stats.halvings;
  }
  if (const auto* rkl2 = thermal::find_integrator<thermal::SuperTimeStepping>(built.integrator.get()))
    summary["run"]["stages"] = rkl2->statistics().stages;
  if (mechanics) summary["run"]["mechanics"] = mechanics->facts();
  if (flow) summary["groundwater"] = groundwater_summary(*p.groundwater, *flow, *gaps, frozen_area, closure->closure_time());
  io::write_text_file(out / "summary.json", summary.dump(2) + "\n");
  if (p.output.report) report::write_report(out);  // from the files just written
}

}  // namespace frostwall::run
