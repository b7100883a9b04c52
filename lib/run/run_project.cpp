#include "run/run_project.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include "run/plain_model.hpp"
#include "io/atomic_file.hpp"
#include "io/point_cloud_vtk.hpp"
#include "post/front.hpp"
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

io::PointCloudFrame frame_of(const sph::ParticleSet<2>& particles, const thermal::ThermalModel& model) {
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

const char* integrator_name(project::IntegratorKind k) {
  return k == project::IntegratorKind::implicit ? "implicit" : "explicit";
}

}  // namespace

void run_project(const Project& p, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  auto note = [&](const std::string& s) {
    if (options.note) options.note(s);
  };
  PlainModel built = build_plain_model(p);
  for (const auto& n : built.scene.notes) note(n);
  const auto& scene = built.scene;
  const auto& face = built.face;
  thermal::ThermalModel& model = *built.model;
  const std::size_t pair_count = model.pairs().pairs();
  const double h = built.h;

  // ---- output
  const fs::path out = p.output.directory;
  fs::create_directories(out);
  const double unit = p.time.unit_seconds();
  const auto stems = snapshot_stems(p.time, "field");
  std::vector<io::PvdEntry> pvd;
  nlohmann::json front = nlohmann::json::array();
  const std::vector<double> times = sample_times(p.time, 200);
  const double heat_before = model.stored_heat();

  thermal::TimeLoopObservers observers;
  observers.progress = options.progress;
  observers.snapshot = [&](const thermal::ThermalModel& m, double t, std::size_t) {
    if (face) {
      const auto x = post::frozen_front(scene.particles.position, m.liquid_fraction(), m.free_count(), *face);
      front.push_back({t / unit, x ? nlohmann::json(*x) : nlohmann::json(nullptr)});
    }
    const auto k = std::lower_bound(p.time.snapshots.begin(), p.time.snapshots.end(), t - 1e-12 * p.time.end) -
                   p.time.snapshots.begin();
    if (p.output.vtk && k < static_cast<long>(stems.size()) && std::abs(p.time.snapshots[k] - t) <= 1e-12 * p.time.end) {
      io::write_vtu(out / (stems[k] + ".vtu"), frame_of(scene.particles, m));
      pvd.push_back({t / unit, stems[k] + ".vtu"});
    }
  };
  const thermal::TimeLoopResult loop = thermal::run_time_loop(model, *built.integrator, p.time.end, times, observers);
  if (p.output.vtk) io::write_pvd(out / "field.pvd", pvd);

  // ---- summary
  const double wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  nlohmann::json boundary_heat = nlohmann::json::object();
  for (std::size_t b = 0; b < scene.boundaries.size(); ++b) boundary_heat[scene.boundaries[b].name] = loop.boundary_heat[b];
  nlohmann::json summary = {
      {"project", p.name},
      {"frostwall_version", FROSTWALL_VERSION},
      {"front", front},
      {"front_axis", face ? nlohmann::json{{"face", face->side}} : nlohmann::json(nullptr)},
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
        {"spacing", scene.particles.spacing},
        {"smoothing_length", h},
        {"kernel", built.kernel->name()},
        {"time_unit", p.time.unit == project::TimeUnit::s ? "s" : (p.time.unit == project::TimeUnit::h ? "h" : "d")}}},
      {"warnings", p.warnings},
  };
  io::write_text_file(out / "summary.json", summary.dump(2) + "\n");
}

}  // namespace frostwall::run
