#include "freezing/heat_run.hpp"
#include "freezing/plant_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <omp.h>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "freezing/brine_log.hpp"
#include "freezing/closure_tracker.hpp"
#include "freezing/excavation_run.hpp"
#include "freezing/balance_log.hpp"
#include "freezing/groundwater_flow.hpp"
#include "freezing/output_frames.hpp"
#include "freezing/plain_results.hpp"
#include "freezing/shaft_results.hpp"
#include "freezing/thermometers.hpp"
#include "io/atomic_file.hpp"
#include "io/output_directory.hpp"
#include "io/paraview_script.hpp"
#include "io/summary_file.hpp"
#include "post/frozen_area_trend.hpp"
#include "post/front.hpp"
#include "post/gap_closure.hpp"
#include "project/units.hpp"
#include "thermal/backward_euler.hpp"
#include "thermal/super_time_stepping.hpp"
#include "thermal/time_loop.hpp"

namespace frostwall::freezing {

namespace fs = std::filesystem;
namespace keys = summary::keys;
using project::Project;

namespace detail {

// One run's state: built once (set-up), updated by the observers of the
// time loop, and turned into the snapshot series and summary.json.
class HeatRun {
 public:
  HeatRun(const Project& p, Model& built, const project::RunOptions& options, RunExtension* extension);
  thermal::TimeLoopObservers observers();
  const std::vector<double>& output_times() const { return times_; }
  // The time (s) of the excavation's next change (infinity: none), and the change.
  double next_event() const {
    return excavation_ ? excavation_->next_event() : std::numeric_limits<double>::infinity();
  }
  void at_event(double t);
  summary::Summary finish(const thermal::TimeLoopResult& loop);

 private:
  void after_step(const thermal::ThermalModel& m, double t);
  void sample_series(const thermal::ThermalModel& m, double t);
  void at_output(const thermal::ThermalModel& m, double t);
  void write_snapshot(const thermal::ThermalModel& m, double t, const std::string& stem);
  void note_for_paraview(const io::PointCloudFrame& frame);
  nlohmann::ordered_json summary(const thermal::TimeLoopResult& loop) const;

  const Project& p_;
  Model& built_;
  const project::RunOptions& options_;
  RunExtension* extension_;
  const fs::path out_;
  const double unit_;
  std::vector<std::string> stems_;
  std::vector<io::PvdEntry> pvd_, ring_pvd_;
  bool write_ring_ = false;
  std::optional<SnapshotFrames> frames_;  // with VTK output
  io::ParaviewScene paraview_;            // what open_in_paraview.py loads
  nlohmann::json front_ = nlohmann::json::array();
  // Shaft sections: the regular series is read from the fields interpolated
  // linearly in time between the two steps around each sample, so only the
  // snapshots cut a step short (landing on all 200 cost RKL2 12 % more rate
  // evaluations on the single ring). Plain geometries sample at step ends.
  std::vector<double> series_, times_;
  GroundwaterFlow* flow_ = nullptr;
  std::optional<post::GapClosure> gaps_;  // under seepage: closure per gap
  post::FrozenAreaTrend frozen_area_;     // and whether an open wall still grows
  std::vector<double> latent_left_;
  int flow_observed_ = 0;
  std::optional<ClosureTracker> closure_;
  std::unique_ptr<ShaftResults> results_;
  std::unique_ptr<PlainResults> plain_;
  std::unique_ptr<BrineLog> brine_;
  std::optional<BalanceLog> balance_;  // plain geometries
  double heat_before_ = 0.0;
  std::size_t next_sample_ = 0;
  double t_before_ = 0.0;
  std::vector<double> f_before_, T_before_, f_at_, T_at_;
  std::optional<Thermometers> thermometers_;  // a shaft section's sensors
  std::unique_ptr<ExcavationRun> excavation_;
  std::vector<double> sensors_at_;
};

HeatRun::HeatRun(const Project& p, Model& built, const project::RunOptions& options, RunExtension* extension)
    : p_(p),
      built_(built),
      options_(options),
      extension_(extension),
      out_(p.output.directory),
      unit_(p.time.unit_seconds()) {
  if (options.note) {  // the scene's notes and the model's warnings, before the run
    for (const auto& n : built.scene->notes) options.note(n);
    for (const auto& w : built.warnings) options.note("warning: " + w);
  }
  fs::create_directories(out_);
  if (!options.project_text.empty()) io::write_text_file(out_ / "project.json", options.project_text);
  stems_ = snapshot_stems(p.time, "field");
  write_ring_ = p.output.vtk && p.output.full_ring && built.shaft && !built.particles().mirrors.empty();
  if (p.output.vtk) {
    std::optional<std::array<double, 2>> plate;
    if (const auto* rect = std::get_if<project::Rectangle>(&p.geometry)) plate = std::array{rect->width, rect->height};
    frames_.emplace(built.particles(), io::file_labels(p), plate);
  }
  series_ = sample_times(p.time, time_series_points);
  // No RKL2 step longer than that interval: on the single ring, longer late
  // steps (a front particle then freezes within one step) cost 0.5-1 cm of
  // wall thickness.
  const double longest_step = p.time.end / time_series_points;
  if (auto* rkl2 = dynamic_cast<thermal::SuperTimeStepping*>(built.integrator.get())) rkl2->limit_step(longest_step);
  // Flowing groundwater: the conduction integrator wrapped with the flow
  // and the heat it carries.
  if (p.groundwater) {
    auto wrapped = std::make_unique<GroundwaterFlow>(p, built);
    flow_ = wrapped.get();
    built.integrator = std::move(wrapped);
    if (built.shaft) {
      gaps_.emplace(built.particles(), geometry::pipe_positions(std::get<project::ShaftSection>(p.geometry).layout),
                    built.shaft->pipe_radius);
      gaps_->observe_flow(0.0, built.particles(), built.model->pairs(), flow_->pair_flux());
    }
    flow_observed_ = flow_->flow_solves();
  }
  // Closure of a shaft section (a fully frozen path) and the day the frozen
  // columns touch: checked 2000 times over the run while the gap is open,
  // at every step once it freezes.
  if (built.shaft) closure_.emplace(built, p.time.end, longest_step);
  times_ = built.shaft ? sample_times(p.time, 0) : series_;
  if (built.shaft) results_ = std::make_unique<ShaftResults>(p, built);
  else {
    plain_ = std::make_unique<PlainResults>(p, built);
    balance_.emplace(*built.model,
                     p.soil.porosity > 0.0 ? p.soil.porosity
                     : p.groundwater       ? p.groundwater->law.porosity
                                           : 0.0,
                     unit_);
  }
  if (extension_ && extension_->solid()) plain_->attach(extension_->solid());
  if (built.shaft && !p.monitoring.empty()) thermometers_.emplace(p, built);
  heat_before_ = built.model->stored_heat();
  if (built.shaft && p.excavation) excavation_ = std::make_unique<ExcavationRun>(p, built);
  if (built.shaft && built.model->boundaries()[built.shaft->pipe_boundary].film)
    brine_ = std::make_unique<BrineLog>(std::get<project::ShaftSection>(p.geometry).pipe, *built.model,
                                        built.shaft->pipe_boundary, series_);
}

thermal::TimeLoopObservers HeatRun::observers() {
  thermal::TimeLoopObservers o;
  o.progress = options_.progress;
  o.after_step = [this](const thermal::ThermalModel& m, double t) { after_step(m, t); };
  if (extension_) o.finished = [this] { return extension_->finished(); };
  if (thermometers_ || excavation_)
    o.step_limit = [this] {
      double limit = thermometers_ ? thermometers_->step_limit() : std::numeric_limits<double>::infinity();
      if (excavation_) limit = std::min(limit, excavation_->step_limit());
      return limit;
    };
  o.snapshot = [this](const thermal::ThermalModel& m, double t, std::size_t) { at_output(m, t); };
  return o;
}

void HeatRun::at_event(double t) {
  excavation_->apply(t);
  if (!results_) return;
  results_->set_face(*excavation_);
  results_->read_event(t, built_.model->liquid_fraction(), built_.model->temperature());
}

void HeatRun::after_step(const thermal::ThermalModel& m, double t) {
  if (excavation_) excavation_->after_step(t);
  if (gaps_) {
    m.latent_left(latent_left_);
    gaps_->observe(t, latent_left_);
    if (flow_->flow_solves() != flow_observed_) {  // the water through each gap, at every new flow
      gaps_->observe_flow(t, built_.particles(), m.pairs(), flow_->pair_flux());
      flow_observed_ = flow_->flow_solves();
    }
    double area = 0.0;
    for (std::size_t i = 0; i < m.free_count(); ++i) area += m.volume()[i] * (1.0 - m.liquid_fraction()[i]);
    frozen_area_.add(t / project::seconds_per_day, area);
  }
  if (closure_) closure_->after_step(m, t, gaps_ ? &*gaps_ : nullptr);
  if (balance_) balance_->after_step(m, t);
  if (brine_) brine_->after_step(m, t);
  if (thermometers_) thermometers_->after_step(m, t);
  if (extension_) extension_->after_step(m, t);
  if (extension_ && thermometers_) extension_->read_sensors(*thermometers_, t);
  if (results_) sample_series(m, t);
}

// The shaft's regular series, interpolated between this step and the last.
void HeatRun::sample_series(const thermal::ThermalModel& m, double t) {
  const auto& f = m.liquid_fraction();
  const auto& T = m.temperature();
  for (; next_sample_ < series_.size() && series_[next_sample_] <= t + 1e-12 * p_.time.end; ++next_sample_) {
    const double tau = series_[next_sample_];
    sensors_at_.resize(thermometers_ ? thermometers_->size() : 0);
    for (std::size_t k = 0; k < sensors_at_.size(); ++k) sensors_at_[k] = thermometers_->at(k, tau);
    const double w = t > t_before_ ? std::clamp((tau - t_before_) / (t - t_before_), 0.0, 1.0) : 1.0;
    if (w >= 1.0 || f_before_.empty()) {
      results_->sample(tau, f, T, sensors_at_);
      continue;
    }
    f_at_.resize(f.size());
    T_at_.resize(T.size());
    for (std::size_t i = 0; i < f.size(); ++i) {
      f_at_[i] = f_before_[i] + w * (f[i] - f_before_[i]);
      T_at_[i] = T_before_[i] + w * (T[i] - T_before_[i]);
    }
    results_->sample(tau, f_at_, T_at_, sensors_at_);
  }
  f_before_.assign(f.begin(), f.end());
  T_before_.assign(T.begin(), T.end());
  t_before_ = t;
}

void HeatRun::at_output(const thermal::ThermalModel& m, double t) {
  const auto& particles = built_.particles();
  if (built_.face) {
    const auto x = post::frozen_front(particles.position, m.liquid_fraction(), m.free_count(), *built_.face);
    front_.push_back({t / unit_, x ? nlohmann::json(*x) : nlohmann::json(nullptr)});
  }
  const auto& snapshots = p_.time.snapshots;
  const auto k = std::lower_bound(snapshots.begin(), snapshots.end(), t - 1e-12 * p_.time.end) - snapshots.begin();
  const bool is_snapshot = k < static_cast<long>(stems_.size()) && std::abs(snapshots[k] - t) <= 1e-12 * p_.time.end;
  const std::string stem = is_snapshot ? stems_[k] : std::string();
  if (results_ && is_snapshot) results_->snapshot(t, m, out_, stem);
  if (extension_) extension_->at_output(m, t, is_snapshot, out_, stem);
  if (plain_) plain_->sample(t, m);
  if (balance_) balance_->sample(m, t);
  if (plain_ && is_snapshot) plain_->snapshot(t, m, out_, stem);
  if (p_.output.vtk && is_snapshot) write_snapshot(m, t, stem);
}

void HeatRun::write_snapshot(const thermal::ThermalModel& m, double t, const std::string& stem) {
  auto all = frame_of(built_.particles(), m);
  if (extension_) extension_->add_fields(all, m);
  if (flow_) flow_->add_fields(all, m);
  const auto frame = frames_->wedge(all);
  io::write_vtu(out_ / (stem + ".vtu"), frame);
  note_for_paraview(frame);
  pvd_.push_back({t / unit_, stem + ".vtu"});
  if (write_ring_) {
    const std::string ring_file = "ring" + stem.substr(5) + ".vtu";
    // The ring's triangles: the shaft results built them at this snapshot
    // for the ring's front curves, over the same copies of the particles.
    const auto* triangles = results_->ring_triangles();
    if (!triangles) throw std::logic_error("ring files without the ring's triangles");
    auto ring = full_ring(frame, built_.particles().mirrors, built_.shaft->far_field_radius);
    ring.triangles = *triangles;
    io::write_vtu(out_ / ring_file, ring);
    ring_pvd_.push_back({t / unit_, ring_file});
  }
}

// The temperature range of the files written, and whether they carry a
// solid, for the ParaView script's colour map.
void HeatRun::note_for_paraview(const io::PointCloudFrame& frame) {
  for (const auto& [name, values] : frame.fields)
    if (name == "temperature" && !values.empty()) {
      const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
      const bool first = pvd_.empty();
      paraview_.coldest = first ? *lo : std::min(paraview_.coldest, *lo);
      paraview_.warmest = first ? *hi : std::max(paraview_.warmest, *hi);
    }
  for (const auto& vector : frame.vectors) paraview_.solid = paraview_.solid || vector.first == "displacement";
}

summary::Summary HeatRun::finish(const thermal::TimeLoopResult& loop) {
  if (p_.output.vtk) io::write_pvd(out_ / "field.pvd", pvd_);
  if (write_ring_) io::write_pvd(out_ / "ring.pvd", ring_pvd_);
  if (p_.output.vtk && !pvd_.empty()) {
    using Kind = io::ParaviewSeries::Kind;
    if (write_ring_) paraview_.series.push_back({"ring.pvd", Kind::temperature, true});
    paraview_.series.push_back({"field.pvd", Kind::temperature, !write_ring_});
    paraview_.title = p_.name;
    paraview_.freezing_point = p_.soil.freezing_point;
    paraview_.isotherm = p_.design.isotherm;
    io::write_paraview_script(out_ / "open_in_paraview.py", paraview_);
  }
  auto result = summary::from_json(summary(loop));
  io::write_summary(out_, result);
  return result;
}

nlohmann::ordered_json HeatRun::summary(const thermal::TimeLoopResult& loop) const {
  const auto& model = *built_.model;
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - built_.started).count();
  nlohmann::json boundary_heat = nlohmann::json::object();
  for (std::size_t b = 0; b < model.boundaries().size(); ++b)
    boundary_heat[model.boundaries()[b].name] = loop.boundary_heat[b];
  // ordered_json: the keys stay in the contract's order.
  nlohmann::ordered_json summary = {{keys::project, p_.name}, {keys::frostwall_version, FROSTWALL_VERSION}};
  if (built_.shaft) {
    const auto closure_time = closure_->closure_time();
    const auto contact_time = closure_->contact_time();
    summary[keys::closure_time_days] = closure_time ? nlohmann::json(*closure_time / project::seconds_per_day)
                                                    : nlohmann::json(nullptr);
    summary[keys::front_contact_days] = contact_time ? nlohmann::json(*contact_time / project::seconds_per_day)
                                                     : nlohmann::json(nullptr);
    const nlohmann::json parts = results_->finish(out_);
    for (const char* key : {keys::wall, keys::design, keys::monitoring, keys::interface})
      if (parts.contains(key)) summary[key] = parts[key];
    summary[keys::thinnest_angle_deg] = parts.value(keys::thinnest_angle_deg, nlohmann::json());
    if (brine_) summary[brine_->summary_key()] = brine_->finish(out_);
    if (excavation_)
      summary[keys::excavation] = excavation_->summary(results_->excavation_entry(excavation_->day()), out_);
    const auto& w = built_.shaft->wedge;
    summary[keys::wedge] = {{"mirror_lines", w.mirror_count},
                            {"start_deg", w.start_angle * 180 / M_PI},
                            {"angle_deg", w.angle * 180 / M_PI}};
  } else {
    summary[keys::front] = front_;
    summary[keys::front_axis] = built_.face ? nlohmann::json{{"face", built_.face->side}} : nlohmann::json(nullptr);
    const nlohmann::json parts = plain_->finish(out_);
    for (const char* key : {keys::front_along, keys::monitoring, keys::monitoring_solid, keys::interface})
      if (parts.contains(key)) summary[key] = parts[key];
    if (extension_) extension_->summarise(summary, out_);
    summary[keys::balance] = balance_->finish(out_);
    const auto thaw = balance_->thaw_time();
    summary[keys::thaw_time] = thaw ? nlohmann::json(*thaw) : nlohmann::json(nullptr);
  }
  const auto& P = built_.particles();
  std::vector<std::string> warnings = p_.warnings;
  warnings.insert(warnings.end(), built_.warnings.begin(), built_.warnings.end());
  if (excavation_) excavation_->add_heat(boundary_heat);  // what it moved in or out, beside the boundaries
  summary.update(nlohmann::ordered_json{
      {keys::heat_balance,
       {{"stored_change", model.stored_heat() - heat_before_}, {"from_boundaries", boundary_heat}, {"unit", "J/m"}}},
      {keys::run,
       {{keys::particles, model.free_count()},
        {"boundary_particles", model.size() - model.free_count()},
        {"pairs", model.pairs().pairs()},
        {keys::steps, loop.steps},
        {keys::wall_seconds, wall_seconds},
        {"threads", omp_get_max_threads()},
        {keys::integrator, integrator_name(p_.numerics.integrator)},
        {"method", p_.numerics.method == project::Method::pd ? "pd" : "sph"},
        {keys::spacing, P.spacing},
        {"placement", P.graded() ? "graded" : "lattice"},
        {"coarsest_spacing", P.coarsest_spacing()},
        {keys::smoothing_length, built_.h},
        {"kernel", built_.kernel->name()},
        {"time_unit", p_.time.unit_name()}}},
      {keys::warnings, warnings},
  });
  if (const auto* implicit = thermal::find_integrator<thermal::BackwardEuler>(built_.integrator.get())) {
    const auto& stats = implicit->statistics();
    summary[keys::run]["newton_iterations"] = stats.newton_iterations;
    summary[keys::run]["linear_iterations"] = stats.linear_iterations;
    summary[keys::run]["step_halvings"] = stats.halvings;
  }
  if (const auto* rkl2 = thermal::find_integrator<thermal::SuperTimeStepping>(built_.integrator.get()))
    summary[keys::run]["stages"] = rkl2->statistics().stages;
  if (const auto* section = std::get_if<project::ShaftSection>(&p_.geometry))
    summary[keys::run]["pipe_model"] = project::pipe_model_name(section->pipe.model);
  if (extension_) extension_->run_facts(summary[keys::run]);
  if (flow_ && gaps_)
    summary[keys::groundwater] =
        groundwater_summary(*p_.groundwater, *flow_, *gaps_, frozen_area_, closure_->closure_time());
  else if (flow_)
    summary[keys::groundwater] = {{"flow_solves", flow_->flow_solves()},
                                  {"inflow_m2_per_s", flow_->inflow_from_boundary()}};
  return summary;
}

}  // namespace detail

summary::Summary run_heat(const Project& p, Model& built, const project::RunOptions& options, RunExtension* extension) {
  SteppedHeatRun run(p, built, options, extension);
  run.advance_to(p.time.end);
  return run.finish();
}

SteppedHeatRun::SteppedHeatRun(const Project& p, Model& built, const project::RunOptions& options,
                               RunExtension* extension)
    : run_(std::make_unique<detail::HeatRun>(p, built, options, extension)),
      loop_(std::make_unique<thermal::TimeLoop>(*built.model, *built.integrator, p.time.end, run_->output_times(),
                                                run_->observers())) {}

SteppedHeatRun::~SteppedHeatRun() = default;

double SteppedHeatRun::advance_to(double t) {
  // Every change of the excavation is landed on, then made.
  for (double e = run_->next_event(); e <= t && !loop_->done(); e = run_->next_event()) {
    loop_->advance_to(e);
    run_->at_event(e);
  }
  return loop_->advance_to(t);
}
bool SteppedHeatRun::done() const { return loop_->done(); }
const thermal::TimeLoopResult& SteppedHeatRun::loop() const { return loop_->result(); }
summary::Summary SteppedHeatRun::finish() { return run_->finish(loop_->result()); }

summary::Summary run(const Project& p, const project::RunOptions& options) {
  if (p.plant) return run_single_plant(p, options);  // the section's brine from its plant's circuit
  check_run_inputs(p);
  Model built = build_model(p);
  return run_heat(p, built, options);
}

}  // namespace frostwall::freezing
