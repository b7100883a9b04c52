// The grain assembly of a CFD-DEM run before the flow opens: the LAMMPS
// set-up from the validated structs, the grains placed or read from the
// packing cache, settling in still water (with a wall round the cavity so
// it stays open, in a taller column if the fill reaches above the box),
// the column trimmed to the box, the packing cached, the cavity's wall
// taken away (the cavity is unlined).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dem/commands.hpp"
#include "dem/lammps_session.hpp"
#include "project/project.hpp"
#include "cfd_dem/coupling.hpp"

namespace frostwall::cfd_dem {

struct GrainSetup {
  std::filesystem::path cache;  // the settled packing's file
  bool cached = false;          // read from it (no settling here)
  bool settle = false;          // settling asked for
  int open_face = -1;           // the face grains may leave through (0..5), or -1
};

// Sends everything up to the motion (set-up, grains, contacts, walls,
// the cavity's wall while settling, gravity, fix external, the step).
GrainSetup set_up_grains(const project::Project& p, dem::LammpsSession& lammps, const std::vector<dem::Grain>& grains,
                         const std::filesystem::path& out, double dt, int interval,
                         const std::function<void(const std::string&)>& note);

// Settles (unless cached), trims a settling column, caches the packing,
// takes the cavity's wall away.
void settle_grains(const project::Project& p, dem::LammpsSession& lammps, CfdDemCoupling& coupling,
                   const GrainSetup& setup, double dt, int interval,
                   const std::function<void(double, double)>& progress,
                   const std::function<void(const std::string&)>& note);

}  // namespace frostwall::cfd_dem
