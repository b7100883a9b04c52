// The run path of a "physics": "cfd-dem" project: resources checked, the
// grains placed (or a settled packing read from the cache), LAMMPS set up
// from the validated structs, settling in still water, then the coupled
// run with samples, snapshots and the output files (written by rank 0).
#include "cfd_dem/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <mpi.h>
#include <numbers>
#include <omp.h>
#include <unistd.h>

#include "dem/commands.hpp"
#include "dem/lammps_session.hpp"
#include "dem/packing.hpp"
#include "io/atomic_file.hpp"
#include "io/summary_file.hpp"
#include "io/grid_vtk.hpp"
#include "io/paraview_script.hpp"
#include "io/point_cloud_vtk.hpp"
#include "io/output_directory.hpp"
#include "cfd_dem/cavity_watch.hpp"
#include "cfd_dem/coupling.hpp"
#include "cfd_dem/results.hpp"
#include "cfd_dem/setup.hpp"
#include "cfd_dem/soil.hpp"
#include "cfd_dem/stability.hpp"

namespace frostwall::cfd_dem {

namespace fs = std::filesystem;
using nlohmann::json;

double dem_timestep(const project::CfdDem& c) {
  if (c.coupling.dem_timestep) return *c.coupling.dem_timestep;
  return 0.2 * project::rayleigh_time(c.grains);  // a fifth of the smallest grain's
}

int coupling_interval(const project::CfdDem& c, double dt, bool flowing) {
  if (c.coupling.interval && flowing) return *c.coupling.interval;
  // Forces are held between fluid updates: for at most 2 % of the smallest
  // grain's Stokes relaxation time, and, once the water flows, no longer
  // than it takes to carry a grain a tenth of its diameter; 1 to 250 steps.
  const double d = c.grains.diameter_min;
  double hold = 0.02 * c.grains.density * d * d / (18.0 * c.fluid.viscosity);
  if (c.flow && flowing)
    for (const auto& [t, u] : c.flow->darcy_velocity)
      if (std::abs(u) > 0.0) hold = std::min(hold, 0.1 * d / std::abs(u));
  return std::clamp(static_cast<int>(hold / dt), 1, 250);
}

void check_cfd_dem_resources(const project::CfdDem& c) {
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  const double grains = static_cast<double>(dem::requested_grains(c));
  const double limit = c.max_grains.value_or(0.5 * memory / bytes_per_grain);
  if (grains > limit)
    throw project::ProjectError({fmt::format("{}: {:.0f} grains exceed the limit of {:.0f} ({}); ask for fewer",
                                             c.grains.count ? "grains.count" : "grains.porosity", grains, limit,
                                             c.max_grains ? "max_grains" : "half this machine's memory")});
  const double cells = static_cast<double>(c.fluid.cells[0]) * c.fluid.cells[1] * c.fluid.cells[2];
  if (cells * bytes_per_cell > 0.25 * memory)
    throw project::ProjectError({fmt::format("{}: {:.0f} cells exceed a quarter of this machine's memory; use {}",
                                             c.fluid.cells_given ? "fluid.cells" : "fluid.cell_size", cells,
                                             c.fluid.cells_given ? "fewer cells" : "larger cells")});
}

namespace {

// The output directory checked by rank 0 alone (the check makes and removes
// it, which ranks doing at once would race over); every rank stops alike.
void check_output_directory_once(const std::string& directory) {
  std::string problem;
  if (dem::world_rank() == 0) try {
      io::check_output_directory(directory);
    } catch (const project::ProjectError& e) {
      problem = e.problems().empty() ? e.what() : e.problems().front();
    }
  int size = static_cast<int>(problem.size());
  MPI_Bcast(&size, 1, MPI_INT, 0, MPI_COMM_WORLD);
  problem.resize(size);
  MPI_Bcast(problem.data(), size, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (size > 0) throw project::ProjectError({problem});
}

// Every rank's grains gathered on rank 0, by id: the snapshot's grain file.
void write_grains(const fs::path& file, const io::Labels& labels, dem::LammpsSession& lammps,
                  const CfdDemCoupling& coupling, const SoilWatch& soil, const CavityWatch& cavity) {
  constexpr int fields = 16;  // id, x3, v3, radius, contacts, force3, lost, displacement3
  const int n = lammps.local_count();
  const int* ids = lammps.ids();
  double** x = lammps.position();
  double** v = lammps.velocity();
  const double* r = lammps.radius();
  const double* contacts = lammps.contacts();
  std::vector<double> mine;
  mine.reserve(static_cast<std::size_t>(n) * fields);
  for (int i = 0; i < n; ++i) {
    const auto f = coupling.fluid_force(ids[i]);
    const auto s = soil.start(ids[i]);
    for (double value :
         {double(ids[i]), x[i][0], x[i][1], x[i][2], v[i][0], v[i][1], v[i][2], r[i], contacts ? contacts[i] : 0.0,
          f[0], f[1], f[2], std::max(cavity.entered(ids[i]), coupling.lost(x[i])), x[i][0] - s[0], x[i][1] - s[1],
          x[i][2] - s[2]})
      mine.push_back(value);
  }
  const int size = static_cast<int>(mine.size());
  std::vector<int> sizes(lammps.ranks()), offsets(lammps.ranks());
  MPI_Gather(&size, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (lammps.rank() == 0) {
    for (int k = 1; k < lammps.ranks(); ++k) offsets[k] = offsets[k - 1] + sizes[k - 1];
    all.resize(offsets.back() + sizes.back());
  }
  MPI_Gatherv(mine.data(), size, MPI_DOUBLE, all.data(), sizes.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  if (lammps.rank() != 0) return;
  const std::size_t count = all.size() / fields;
  std::vector<std::size_t> order(count);
  for (std::size_t i = 0; i < count; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return all[a * fields] < all[b * fields]; });
  io::PointCloudFrame frame;
  std::vector<double> diameter, contact, lost, velocity, force, displacement;
  for (std::size_t i : order) {
    const double* g = &all[i * fields];
    frame.points.push_back({g[1], g[2], g[3]});
    velocity.insert(velocity.end(), {g[4], g[5], g[6]});
    diameter.push_back(2.0 * g[7]);
    contact.push_back(g[8]);
    force.insert(force.end(), {g[9], g[10], g[11]});
    lost.push_back(g[12]);
    displacement.insert(displacement.end(), {g[13], g[14], g[15]});
  }
  std::vector<double> radius(diameter.size());
  for (std::size_t i = 0; i < radius.size(); ++i) radius[i] = 0.5 * diameter[i];  // Point Gaussian, Glyph scale
  frame.fields = {{"diameter", diameter}, {"radius", radius}, {"contacts", contact}, {"lost", lost}};
  frame.labels = labels;
  frame.vectors = {{"velocity", velocity}, {"fluid_force", force}, {"displacement", displacement}};
  io::write_vtu(file, frame);
}

void write_fluid(const fs::path& file, const io::Labels& labels, const pore_water::FluidGrid& grid) {
  const auto& s = grid.shape();
  io::GridFrame frame;
  for (int k = 0; k < 3; ++k)
    frame.origin[k] = s.low[k], frame.spacing[k] = s.cell_size(k), frame.cells[k] = s.cells[k];
  std::vector<double> velocity;
  for (const auto& u : grid.superficial_velocity()) velocity.insert(velocity.end(), {u[0], u[1], u[2]});
  frame.fields = {{"porosity", grid.porosity()}, {"pressure", grid.pressure()}};
  frame.vectors = {{"superficial_velocity", velocity}};
  frame.labels = labels;
  io::write_vti(file, frame);
}

// What the flow after settling leaves: the series, the soil record, the
// grains lost and the snapshot files.
struct FlowRecord {
  CfdDemResults results;
  SoilRecord soil_record;
  double lost_cavity = 0.0, lost_outflow = 0.0, start_volume = -1.0;
  std::vector<io::PvdEntry> grain_pvd, fluid_pvd;
};

// The coupled steps to the end time: a sample 200 times, the snapshots on
// their times, and the grains that leave counted after every chunk.
void run_flow(const project::Project& p, dem::LammpsSession& lammps, CfdDemCoupling& coupling, const SoilWatch& soil,
              CavityWatch& cavity, StabilityWatch& stability, double dt, long total_steps, const fs::path& out,
              const std::function<void(double, double)>& progress, FlowRecord& rec) {
  const auto& c = *p.cfd_dem;
  const bool root = lammps.rank() == 0;
  std::vector<double> samples;
  for (int k = 0; k <= 200; ++k) samples.push_back(p.time.end * k / 200.0);
  const auto& snapshots = p.time.snapshots;
  const bool drain = c.cavity && c.cavity->drain;
  std::size_t next_sample = 0, next_snapshot = 0;
  long step = 0;
  while (true) {
    const double t = step * dt;
    const double u = c.flow ? c.flow->velocity_at(t) : 0.0;
    const pore_water::SolveReport report = coupling.update(u);
    const bool last = step >= total_steps;
    const bool is_sample = next_sample < samples.size() && t >= samples[next_sample] - 0.5 * dt;
    const bool is_snapshot = next_snapshot < snapshots.size() && (t >= snapshots[next_snapshot] - 0.5 * dt || last);
    if (is_sample || is_snapshot || last) {
      const auto totals = coupling.totals();
      if (rec.start_volume < 0.0) rec.start_volume = totals.volume;
      rec.results.add(rec.results.sample(t, u, totals, coupling.grid(), report), is_snapshot);
      // A kept cavity: its grains stay in the model, counted once they entered.
      if (!drain) rec.lost_cavity = cavity.count();
      const double soil_grains = drain ? totals.count - totals.in_cavity : totals.count - rec.lost_cavity;
      rec.soil_record.add({t, soil_grains, rec.lost_cavity, rec.lost_outflow, totals.contacts, soil.measure(coupling),
                           totals.in_cavity, totals.count},
                          is_snapshot);
      while (next_sample < samples.size() && samples[next_sample] <= t + 0.5 * dt) ++next_sample;
    }
    if (is_snapshot) {
      const std::string stem = fmt::format("{:04d}", next_snapshot + 1);
      if (p.output.vtk) {
        const auto labels = io::file_labels(p, "s");  // the collections' times are in seconds
        write_grains(out / ("grains_" + stem + ".vtu"), labels, lammps, coupling, soil, cavity);
        if (root) write_fluid(out / ("fluid_" + stem + ".vti"), labels, coupling.grid());
        rec.grain_pvd.push_back({t, "grains_" + stem + ".vtu"});
        rec.fluid_pvd.push_back({t, "fluid_" + stem + ".vti"});
      }
      ++next_snapshot;
    }
    if (progress && root) progress(std::min(t, p.time.end), p.time.end);
    if (last) break;
    long steps = std::min<long>(stability.next_interval(coupling), total_steps - step);
    // A snapshot lands on its time: the chunk before it is cut short.
    if (next_snapshot < snapshots.size()) {
      const long to_snapshot = std::lround(std::ceil((snapshots[next_snapshot] - t) / dt - 1e-9));
      if (to_snapshot >= 1) steps = std::min(steps, to_snapshot);
    }
    const long before = lammps.grain_count();
    coupling.advance(steps);
    step += steps;
    // Grains gone through an open outflow face, then those fallen into the
    // cavity: marked where it keeps them, deleted where a leak drains it.
    const long after_run = lammps.grain_count();
    if (drain) lammps.command(dem::delete_in_cavity);
    else cavity.observe();
    rec.lost_outflow += static_cast<double>(before - after_run);
    rec.lost_cavity += static_cast<double>(after_run - lammps.grain_count());
    const double t_end = step * dt;
    stability.check(t_end, coupling, next_sample < samples.size() && t_end >= samples[next_sample] - 0.5 * dt);
  }
}

// The set-up as LAMMPS input (runs and the cache's write_restart left out):
// `lmp -in dem_commands.txt` rebuilds the assembly from this directory's
// working directory.
std::string dem_commands(const dem::LammpsSession& lammps, const project::CfdDem& c, int interval, long total_steps) {
  std::string commands =
      fmt::format("# frostwall {}: the LAMMPS commands of this run's grain assembly\n", FROSTWALL_VERSION);
  for (const auto& line : lammps.commands())
    if (!line.starts_with("run ") && !line.starts_with("write_restart ") && line != dem::delete_in_cavity)
      commands += line + "\n";
  commands += fmt::format(
      "# then, every {} steps: the fluid grid is solved and each grain's fluid force set\n"
      "# (fix {} external, from frostwall; {}), and `run {}` follows; {} steps in all.\n"
      "# To run the grains without the water: unfix {}\n{}",
      interval, dem::fluid_fix,
      c.coupling.drag == project::DragCoupling::semi_implicit ? "the drag as K (u - v) with each step's grain velocity"
                                                              : "held as a force",
      interval, total_steps, dem::fluid_fix,
      c.cavity && c.cavity->drain ? fmt::format("# after every run: {}\n", dem::delete_in_cavity) : "");
  return commands;
}

}  // namespace

summary::Summary run_cfd_dem(const project::Project& p, const project::RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const auto& c = *p.cfd_dem;
  check_cfd_dem_resources(c);
  const auto grains = dem::initial_grains(c);  // refuses a count that does not fit
  check_output_directory_once(p.output.directory);
  const double dt = dem_timestep(c);
  const int interval = coupling_interval(c, dt, true);
  // Settling is in still water at the interval chosen for it, whatever the
  // flow and coupling.interval later: variants that differ only in those
  // share one settled packing.
  const int settle_interval = coupling_interval(c, dt, false);

  // LAMMPS's own log beside the results: where it explains an abort.
  if (dem::world_rank() == 0) fs::create_directories(p.output.directory);
  dem::world_barrier();
  dem::LammpsSession lammps((fs::path(p.output.directory) / "lammps.log").string());
  const bool root = lammps.rank() == 0;
  // Several ranks on one machine: one thread each for the fluid's solver
  // (Eigen's OpenMP), unless the user set the threads.
  if (lammps.ranks() > 1 && !std::getenv("OMP_NUM_THREADS")) omp_set_num_threads(1);
  auto note = [&](const std::string& s) {
    if (root && options.note) options.note(s);
  };
  const fs::path out = p.output.directory;
  if (root && !options.project_text.empty()) io::write_text_file(out / "project.json", options.project_text);
  const GrainSetup setup = set_up_grains(p, lammps, grains, out, dt, settle_interval, note);
  CfdDemCoupling coupling(c, lammps);
  // A cached packing continues as it was settled: its fluid forces are in
  // place before LAMMPS computes the first forces, which the first step uses.
  if (setup.cached) coupling.update(c.flow ? c.flow->velocity_at(0.0) : 0.0);
  lammps.command("run 0 post no");  // forces, neighbour lists and computes set up before anything reads them
  note(fmt::format("cfd-dem: {} grains on {} rank(s), DEM step {:.3g} s, fluid every {} steps", lammps.grain_count(),
                   lammps.ranks(), dt, interval));

  settle_grains(p, lammps, coupling, setup, dt, settle_interval, options.progress, note);
  if (setup.settle && !setup.cached) {
    // Settled here: the flow starts as it would from the cache just written
    // (the fluid forces in place, then LAMMPS's set-up), so both starts agree.
    coupling.update(c.flow ? c.flow->velocity_at(0.0) : 0.0);
    lammps.command("run 0 post no");
  }
  if (c.heap) {  // the container's sides lifted off the settled block
    const auto [low, high] = dem::heap_container(c);
    for (const auto& s : dem::lifted_block_commands(low, high, dem::dem_contact(c), c.heap->lift_speed, lammps.time()))
      lammps.command(s);
    lammps.command("run 0 post no");  // the runs skip their set-up: a new fix needs one
  }

  // The run proper (after any settling) is what the rates are of.
  const auto flow_start = std::chrono::steady_clock::now();
  const double coupling_before = coupling.coupling_seconds();
  FlowRecord rec{CfdDemResults(p), SoilRecord(c), 0.0, 0.0, -1.0, {}, {}};
  const SoilWatch soil(c, lammps);
  CavityWatch cavity(c, lammps);
  cavity.observe();  // none as settled: the wall held the void open
  const long total_steps = std::max(1L, std::lround(p.time.end / dt));
  StabilityWatch stability(c, dt, interval);
  run_flow(p, lammps, coupling, soil, cavity, stability, dt, total_steps, out, options.progress, rec);

  const auto now = std::chrono::steady_clock::now();
  const double wall = std::chrono::duration<double>(now - wall_start).count();
  const double flow_wall = std::chrono::duration<double>(now - flow_start).count();
  const double coupling_seconds = coupling.coupling_seconds() - coupling_before;
  const json stability_summary = stability.summary(coupling);  // collective
  if (!root) return {};
  if (p.output.vtk) {
    io::write_pvd(out / "grains.pvd", rec.grain_pvd);
    io::write_pvd(out / "fluid.pvd", rec.fluid_pvd);
    using Kind = io::ParaviewSeries::Kind;
    io::ParaviewScene scene;
    scene.title = p.name;
    scene.series = {{"grains.pvd", Kind::grains, true}, {"fluid.pvd", Kind::fluid, false}};
    io::write_paraview_script(out / "open_in_paraview.py", scene);
  }
  io::write_text_file(out / "dem_commands.txt", dem_commands(lammps, c, interval, total_steps));
  io::write_text_file(out / "series.csv", rec.results.csv());
  io::write_text_file(out / "soil.csv", rec.soil_record.csv());
  const json facts = {
      {"grains", lammps.grain_count()},
      {"ranks", lammps.ranks()},
      {"dem_timestep_s", dt},
      {"coupling_interval", interval},
      {"dem_steps", total_steps},
      {"fluid_cells", c.fluid.cells},
      {"fluid_forces", c.forces},
      {"packing",
       {{"cache", setup.cache.string()}, {"read_from_cache", setup.cached}, {"settle_time_s", c.grains.settle_time}}},
      {"wall_time_s", wall},
      {"run_wall_time_s", flow_wall},  // after settling: the DEM steps counted in dem_steps
      {"coupling_seconds", coupling_seconds},
      {"coupling_share", flow_wall > 0 ? coupling_seconds / flow_wall : 0.0}};
  json doc = rec.results.summary(facts);
  doc["stability"] = stability_summary;
  doc[summary::keys::soil] =
      rec.soil_record.summary(packing_regime(c, std::max(0.0, rec.start_volume)), soil.bins(), soil.initial_surface());
  if (c.heap)
    doc["angle_of_repose_deg"] =
        doc[summary::keys::soil].value("heap", json::object()).value("angle_of_repose_deg", json(nullptr));
  if (c.cavity)
    doc[summary::keys::soil]["cavity"] = {
        {"mode", c.cavity->drain ? "drain" : "keep"},
        {"capacity_grains", cavity.capacity()},
        {"meaning", c.cavity->drain ? "grains whose centre enters the cavity are taken away by a leak (deleted)"
                                    : "grains that fall into the cavity stay and fill it"}};
  auto result = summary::from_json(doc);
  io::write_summary(out, result);
  return result;
}

}  // namespace frostwall::cfd_dem
