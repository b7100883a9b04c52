#include "run/check_project.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <fmt/format.h>

#include "cfd_dem/run.hpp"
#include "dem/packing.hpp"
#include "design/coaxial_pipe.hpp"
#include "freezing/capacity.hpp"
#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"
#include "freezing/plant_run.hpp"
#include "geometry/layout.hpp"
#include "io/output_directory.hpp"
#include "run/run_project.hpp"
#include "thermal/phase_change.hpp"

namespace frostwall::run {

namespace {

// Run-time rates, all measured on the shared 2-core machine of
// bench/README.md (2 threads; 1 rank for the grains). A work unit per
// engine, and the rate at which the benchmark case got through it:
//
// SPH, explicit steps: particle-steps per second. Paper mode on the single
// ring, 21 738 particles x 110 472 steps in 46.5 s ("Paper mode against
// default mode").
constexpr double sph_explicit_rate = 21738.0 * 110472.0 / 46.5;
// Adaptive steps (rkl2, implicit) take as many steps as the physics asks,
// each of about sqrt(step / explicit step) stages: the work is counted as
// particles x sqrt(simulated time / explicit step), and the rates are
// calibrated on one case each (particles x sqrt(its explicit steps, as
// `frostwall check` prints them) over its wall time):
// - SPH: the single ring's default mode, 6 707 particles to 120 d (1.74e5
//   explicit steps) in 1.47 s ("Paper mode against default mode");
// - PD heat with mechanics: the PD paper's plate, 10 000 particles to 400 s
//   (5.79e4 explicit steps) in 8.4 s ("PD: the plate at the paper's resolution");
// - PD with pores (frost damage, converged crack cascades): the shipped
//   mortar plate at 3 um, 9 801 particles to 0.12 s (6.09e4 explicit
//   steps) in 1 139.5 s beside a main job of 7.6 s on a loaded machine,
//   so about 416 s where the main job takes its 2.77 s ("Frost damage: the
//   mortar plate").
const double sph_adaptive_rate = 6707.0 * std::sqrt(1.74e5) / 1.47;
// A full ring placed without symmetry (an as-built section) runs slower per
// particle than the wedge: the main job's ring with "symmetry": "none",
// 347 894 particles, in 124.4 s on 2 threads against the 76.2 s of the rate
// above ("The shaft as built").
constexpr double sph_full_ring_factor = 124.4 / 76.2;
const double pd_plate_rate = 10000.0 * std::sqrt(5.79e4) / 8.4;
const double pd_frost_rate = 9801.0 * std::sqrt(6.09e4) / 416.0;
// Implicit steps under flow (the coupled step): the step is held at a
// 200th of the run (shorter only while a gap closes), each a few Newton
// iterations over every particle, so the run's length barely counts and
// the work is the particle count: the shipped seepage reference, 44 963
// particles to 90 d, in 127 s on 2 threads ("Seepage side by side with the
// finite-element peer").
// Otherwise the implicit step follows the freezing activity (a quarter
// of the latent heat a step) like the adaptive steps above, and is counted
// as they are: the single ring in sand with "integrator": "implicit", 6 707
// particles to 120 d (1.74e5 explicit steps), in 65 s on 2 threads.
constexpr double implicit_rate = 44963.0 / 127.0;
const double implicit_still_rate = 6707.0 * std::sqrt(1.74e5) / 65.0;
// CFD-DEM: grain-steps per second on one core, the paper's leak case at
// full size (settled packing, 116 000 grains; "CFD-DEM: the paper's leak
// case at full size": 2.5e6 per core on 2 ranks).
constexpr double dem_rate = 2.5e6;

std::string duration(double seconds) {
  if (seconds < 90) return fmt::format("{:.2g} s", seconds);
  if (seconds < 5400) return fmt::format("{:.2g} min", seconds / 60);
  return fmt::format("{:.2g} h", seconds / 3600);
}

std::string estimate(double seconds, const std::string& basis) {
  return fmt::format("run time: about {} (an estimate for a 2-core machine like bench/README.md's, {})",
                     duration(seconds), basis);
}

std::string unit_of_time(const project::TimeSettings& t) {
  return t.unit == project::TimeUnit::d ? "d" : (t.unit == project::TimeUnit::h ? "h" : "s");
}

std::vector<std::string> check_heat(const project::Project& p, Engine engine) {
  freezing::check_run_inputs(p);
  const freezing::Model m = freezing::build_cloud(p);  // the cloud only: the pairs and solver are the run's set-up
  const auto& P = m.particles();
  const bool pd = p.numerics.method == project::Method::pd;
  const auto* rect = std::get_if<project::Rectangle>(&p.geometry);
  std::vector<std::string> lines;
  std::string what = pd ? "PD heat conduction" : "SPH heat conduction";
  if (engine == Engine::mechanics && p.mechanics) what += " with PD mechanics";
  if (rect && !rect->pores.empty()) what += " and frost in pores";
  lines.push_back("engine: " + what + (rect ? " on a rectangle" : " on a shaft section"));
  if (const auto* section = std::get_if<project::ShaftSection>(&p.geometry)) {
    // The numbers a survey and failed_pipes use.
    for (const auto& q : geometry::all_pipe_positions(section->layout))
      lines.push_back(fmt::format("pipe {}: {} at ({:.3f}, {:.3f}) m, {:.2f} deg{}", q.number, q.label, q.x, q.y,
                                  std::atan2(q.y, q.x) * 180.0 / std::numbers::pi, q.failed ? ", failed (off)" : ""));
  }
  if (p.excavation) {
    const auto& e = *p.excavation;
    const auto radius = std::get<project::ShaftSection>(p.geometry).shaft.excavation_radius.value_or(0.0);
    std::size_t taken = 0;
    for (std::size_t i = 0; i < P.n_free; ++i) taken += P.position[i].norm() < radius;
    std::string line = fmt::format("excavation: dug on day {:g} (depth {:g} m), {} particles taken out inside {:g} m; "
                                   "air film {:g} W/(m2 K)",
                                   e.day(), e.depth, taken, radius, e.heat_transfer);
    if (e.lining)
      line += fmt::format("; a {:g} m lining {:g} d later, {:g} kJ/kg of hydration heat", e.lining->thickness,
                          e.lining->placed_after / 86400.0, e.lining->hydration.final() / 1e3);
    lines.push_back(line);
  }
  lines.push_back(fmt::format("particles: {} free, {} on boundaries", P.n_free, P.size() - P.n_free));
  lines.push_back(fmt::format("memory: at most about {:.0f} MB",
                              static_cast<double>(P.n_free) * freezing::bytes_per_particle / 1e6));
  std::string spacing = fmt::format("spacing: {:.4g} m", m.spacing);
  if (P.graded()) spacing += " (finest; graded coarser away from the pipes and fronts)";
  if (m.rectangle && (m.rectangle->spacing[0] != m.spacing || m.rectangle->spacing[1] != m.spacing))
    spacing += fmt::format(" asked; {:.6g} m along x and {:.6g} m along y to fit the rectangle",
                           m.rectangle->spacing[0], m.rectangle->spacing[1]);
  lines.push_back(spacing);
  double diffusivity = thermal::PhaseChangeLaw(p.soil).max_diffusivity();
  if (rect && !rect->pores.empty())
    diffusivity = std::max(diffusivity, thermal::pore_water_law(p.pore_fluid).max_diffusivity());
  const double dt = p.numerics.beta * m.h * m.h / diffusivity;  // as freezing::build_model's explicit step
  const double explicit_steps = p.time.end / dt;
  const double t_unit = p.time.unit_seconds();
  const std::string end = fmt::format("{:g} {}", p.time.end / t_unit, unit_of_time(p.time));
  const double work = static_cast<double>(P.n_free) * std::sqrt(explicit_steps);
  if (p.numerics.integrator == project::IntegratorKind::explicit_euler) {
    lines.push_back(
        fmt::format("time step: {:.3g} s (explicit), {:.0f} steps to {}", dt, std::ceil(explicit_steps), end));
    lines.push_back(estimate(static_cast<double>(P.n_free) * std::ceil(explicit_steps) / sph_explicit_rate,
                             "at the explicit single ring's particle-steps per second"));
    return lines;
  }
  const char* integrator = p.numerics.integrator == project::IntegratorKind::rkl2 ? "rkl2" : "implicit";
  lines.push_back(fmt::format("time step: adaptive ({}) to {}; the explicit limit would be {:.3g} s ({:.3g} steps)",
                              integrator, end, dt, explicit_steps));
  const bool coupled = p.groundwater && p.groundwater->flows_coupled();
  if (p.numerics.integrator == project::IntegratorKind::implicit && !coupled)
    return lines.push_back(estimate(work / implicit_still_rate, "scaled from the single ring's implicit run")), lines;
  if (p.numerics.integrator == project::IntegratorKind::implicit)
    return lines.push_back(estimate(static_cast<double>(P.n_free) / implicit_rate,
                                    "scaled by the particle count from the seepage reference's; under a flux well "
                                    "above the critical one, where less freezes, down to a quarter of that")),
           lines;
  if (!pd && m.shaft && m.shaft->wedge.mirror_count == 0)
    return lines.push_back(estimate(work / sph_adaptive_rate * sph_full_ring_factor,
                                    "scaled from the 26-pipe ring placed without symmetry")),
           lines;
  if (!pd)
    return lines.push_back(estimate(work / sph_adaptive_rate, "scaled from the single ring's default run")), lines;
  if (rect && !rect->pores.empty())
    return lines.push_back(
               estimate(work / pd_frost_rate, "scaled from the mortar plate's; crack cascades can take far longer")),
           lines;
  lines.push_back(estimate(work / pd_plate_rate, "scaled from the PD paper's plate"));
  return lines;
}

std::vector<std::string> check_grains(const project::Project& p) {
  const auto& c = *p.cfd_dem;
  cfd_dem::check_cfd_dem_resources(c);
  const auto grains = dem::initial_grains(c);  // refuses a count that does not fit
  io::check_output_directory(p.output.directory);
  const double dt = cfd_dem::dem_timestep(c);
  const int interval = cfd_dem::coupling_interval(c, dt, true);
  const long steps = std::max(1L, std::lround(p.time.end / dt));
  const long settle_steps = std::lround(c.grains.settle_time / dt);
  const double cells = static_cast<double>(c.fluid.cells[0]) * c.fluid.cells[1] * c.fluid.cells[2];
  const bool cached = settle_steps > 0 &&
                      std::filesystem::exists(dem::packing_cache_file(c, dt, cfd_dem::coupling_interval(c, dt, false)));
  std::vector<std::string> lines;
  lines.push_back("engine: CFD-DEM (grains in LAMMPS, pore water on a coarse grid)");
  lines.push_back(
      fmt::format("grains: {} of {:.3g} to {:.3g} m", grains.size(), c.grains.diameter_min, c.grains.diameter_max));
  lines.push_back(fmt::format("fluid cells: {} x {} x {}", c.fluid.cells[0], c.fluid.cells[1], c.fluid.cells[2]));
  lines.push_back(fmt::format(
      "memory: about {:.0f} MB",
      (static_cast<double>(grains.size()) * cfd_dem::bytes_per_grain + cells * cfd_dem::bytes_per_cell) / 1e6));
  lines.push_back(
      fmt::format("time step: {:.3g} s ({:.2f} of the smallest grain's Rayleigh time), fluid every {} steps", dt,
                  dt / project::rayleigh_time(c.grains), interval));
  std::string settle = settle_steps == 0
                           ? "no settling"
                           : fmt::format("{} settling steps ({:g} s){}", settle_steps, c.grains.settle_time,
                                         cached ? ", skipped: the settled packing is cached" : "");
  lines.push_back(fmt::format("steps: {} to {:g} s, {}", steps, p.time.end, settle));
  const double grain_steps = static_cast<double>(grains.size()) *
                             static_cast<double>(steps + (cached ? 0 : settle_steps));
  lines.push_back(estimate(grain_steps / dem_rate,
                           "on one rank at the leak case's grain-steps per second; about half with mpirun -np 2"));
  return lines;
}

}  // namespace

std::vector<std::string> check_project(const project::Project& p) {
  if (!p.layers.empty())
    throw project::ProjectError({"layers: a layered project is checked layer by layer (frostwall check does it)"});
  const Engine engine = engine_of(p);
  if (engine == Engine::cfd_dem) return check_grains(p);
  auto lines = check_heat(p, engine);
  // The twins' particles add up to about 1.4 times the run's, with fewer
  // steps: 0.91 of the main job's CPU time (bench/README.md).
  if (p.numerics.error_estimate)
    lines.push_back(
        "error estimate: three coarser runs after it (1.35, 1.5 and 1.65 times the spacing), about as long again");
  return lines;
}

std::string describe_plant(const project::Project& p, std::size_t sections) {
  const auto& plant = *p.plant;
  const auto s = freezing::circuit_settings(p);
  const auto r = design::coaxial_resistances(s.pipe, s.brine, s.flow);
  const double coldest = plant.capacity ? plant.min_supply_temperature : s.supply.points.front().second;
  const std::string supply =
      plant.capacity
          ? fmt::format("{:g} kW, supply no colder than {:g} C", *plant.capacity / 1e3, plant.min_supply_temperature)
          : fmt::format("supply {:g} C{}", coldest, s.supply.constant() ? "" : " (schedule)");
  return fmt::format(
      "plant: {} pipes with flow, {:g} m3/h each down the {}; annulus Re {:.0f}, h {:.0f} W/(m2 K) at {:g} C; {}; "
      "{} section{} coupled through the brine, exchanges every {:g} h (up to {:g} h once the brine settles)",
      s.pipes, s.flow * 3600.0, plant.channel == project::SupplyChannel::annulus ? "annulus" : "inner pipe",
      r.annulus.reynolds, r.annulus.h, s.supply.at(0.0), supply, sections, sections == 1 ? "" : "s",
      plant.exchange_interval / 3600.0, plant.longest_exchange_interval / 3600.0);
}

}  // namespace frostwall::run
