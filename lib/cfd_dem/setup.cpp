#include "cfd_dem/setup.hpp"

#include <cmath>
#include <fmt/format.h>
#include <mpi.h>
#include <unistd.h>

#include "dem/packing.hpp"
#include "io/atomic_file.hpp"

namespace frostwall::cfd_dem {

namespace fs = std::filesystem;

namespace {

dem::Neighbour neighbour(const project::CfdDem& c) {
  return {c.neighbour.skin.value_or(0.25 * c.grains.diameter_max), c.neighbour.every,
          c.neighbour.bin_size.value_or(0.0)};
}

}  // namespace

GrainSetup set_up_grains(const project::Project& p, dem::LammpsSession& lammps, const std::vector<dem::Grain>& grains,
                         const fs::path& out, double dt, int interval,
                         const std::function<void(const std::string&)>& note) {
  const auto& c = *p.cfd_dem;
  GrainSetup setup;
  setup.cache = dem::packing_cache_file(c, dt, interval);
  setup.settle = c.grains.settle_time > 0.0 && !c.grains.held;
  setup.cached = setup.settle && fs::exists(setup.cache);
  if (c.flow && c.flow->open_to_grains) setup.open_face = static_cast<int>(c.flow->outflow);
  auto contact = dem::dem_contact(c);
  const bool settling_here = setup.settle && !setup.cached;
  if (settling_here && c.grains.settle_friction) contact.friction = *c.grains.settle_friction;
  // The cache is a LAMMPS restart file: the packing's geometry, velocities
  // and spins, and its contacts' tangential and rolling springs, which the
  // same pair style and walls (same fix ids) below pick up again.
  const auto box = setup.cached ? dem::dem_box(c) : dem::settling_box(c);
  if (setup.cached) {
    note("packing: settled grains read from the cache " + setup.cache.string());
    for (const auto& s : dem::restart_setup_commands(project::gravity_axis(c))) lammps.command(s);
    lammps.command(dem::read_restart_command(setup.cache.string()));
  } else {
    for (const auto& s : dem::setup_commands(box, project::gravity_axis(c))) lammps.command(s);
    if (lammps.rank() == 0) io::write_text_file(out / "dem_initial.data", dem::data_file(box, grains));
    MPI_Barrier(MPI_COMM_WORLD);
    lammps.command(dem::read_data_command((out / "dem_initial.data").string()));
  }
  for (const auto& s : dem::contact_commands(box, contact, neighbour(c), setup.open_face)) lammps.command(s);
  if (c.cavity) {
    lammps.command(dem::cavity_region_command(c.cavity->centre, c.cavity->radius));
    if (settling_here)
      for (const auto& s : dem::cavity_wall_commands(c.cavity->centre, c.cavity->radius, contact)) lammps.command(s);
  }
  if (c.heap && settling_here) {
    // The heap's grains settle in a container over the fill region, open to the box's top.
    const auto [low, high] = dem::heap_container(c);
    for (const auto& s : dem::block_wall_commands(low, high, contact)) lammps.command(s);
  }
  for (const auto& s : dem::motion_commands(c.gravity, dt, c.grains.held)) lammps.command(s);
  return setup;
}

void settle_grains(const project::Project& p, dem::LammpsSession& lammps, CfdDemCoupling& coupling,
                   const GrainSetup& setup, double dt, int interval,
                   const std::function<void(double, double)>& progress,
                   const std::function<void(const std::string&)>& note) {
  const auto& c = *p.cfd_dem;
  if (!setup.settle || setup.cached) return;
  const bool column = dem::has_settling_column(c);
  const long chunks = std::max(1L, std::lround(c.grains.settle_time / (dt * interval)));
  for (long k = 0; k < chunks; ++k) {
    // The grid does not reach a settling column: gravity and buoyancy only there.
    if (column) coupling.hold_buoyancy_only();
    else coupling.update(0.0);
    coupling.advance(interval);
    if (progress && lammps.rank() == 0) progress(-c.grains.settle_time * (1.0 - double(k + 1) / chunks), p.time.end);
  }
  if (column) {
    // The ground's surface: grains whose centre is above the box's top,
    // less half the largest grain, are taken away.
    const long before = lammps.grain_count();
    for (const auto& s : dem::trim_commands(dem::dem_box(c), 2, c.box.high[2] - 0.5 * c.grains.diameter_max,
                                            dem::dem_contact(c), setup.open_face))
      lammps.command(s);
    note(fmt::format("packing: {} of {} grains above the box's top taken away after settling",
                     before - lammps.grain_count(), before));
  }
  if (c.cavity)
    for (const auto& s : dem::remove_cavity_wall_commands()) lammps.command(s);
  if (c.heap)  // the container lifted: the block slumps into a heap as the run starts
    for (const auto& s : dem::remove_block_wall_commands()) lammps.command(s);
  if (c.grains.settle_friction)  // the run's friction from here on
    for (const auto& s : dem::new_contact_commands(dem::dem_box(c), dem::dem_contact(c), setup.open_face))
      lammps.command(s);
  // Cached under a temporary name, renamed when complete.
  const fs::path tmp = setup.cache.string() + fmt::format(".tmp-{}", getpid());
  if (lammps.rank() == 0) fs::create_directories(setup.cache.parent_path());
  MPI_Barrier(MPI_COMM_WORLD);
  lammps.command(dem::write_restart_command(tmp.string()));
  if (lammps.rank() == 0) fs::rename(tmp, setup.cache);
  note("packing: settled for " + fmt::format("{:g}", c.grains.settle_time) + " s, cached as " + setup.cache.string());
}

}  // namespace frostwall::cfd_dem
