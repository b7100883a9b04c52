#include "dem/lammps_session.hpp"

#include <cstdint>
#include <cstdlib>
#include <mpi.h>
#include <stdexcept>
// The API's MPI form and its integer sizes as this build was compiled
// (LAMMPS_SMALLBIG comes from the LAMMPS::lammps CMake target).
#define LAMMPS_LIB_MPI
#include <lammps/library.h>

namespace frostwall::dem {

LammpsSession::LammpsSession() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (!initialised) {
    MPI_Init(nullptr, nullptr);
    // Finalised once, at exit, however many sessions a process made.
    std::atexit([] {
      int finalised = 0;
      MPI_Finalized(&finalised);
      if (!finalised) MPI_Finalize();
    });
  }
  const char* args[] = {"frostwall", "-log", "none", "-screen", "none", "-nocite"};
  lammps_ = lammps_open(6, const_cast<char**>(args), MPI_COMM_WORLD, nullptr);
  if (!lammps_) throw std::runtime_error("LAMMPS could not be started");
}

LammpsSession::~LammpsSession() {
  if (lammps_) lammps_close(lammps_);
}

void LammpsSession::command(const std::string& line) {
  commands_.push_back(line);
  lammps_command(lammps_, line.c_str());
}

void LammpsSession::run(long steps) {
  command("run " + std::to_string(steps) + " pre no post no");
}

double** LammpsSession::velocity() const { return static_cast<double**>(lammps_extract_atom(lammps_, "v")); }

void LammpsSession::set_external_force(const std::string& fix_id, ForceFunction f) {
  force_ = std::move(f);
  lammps_set_fix_external_callback(lammps_, fix_id.c_str(), &LammpsSession::callback, this);
}

void LammpsSession::callback(void* self, std::int64_t, int n, int*, double** x, double** force) {
  auto* session = static_cast<LammpsSession*>(self);
  if (session->force_) session->force_(n, x, force);
}

}  // namespace frostwall::dem
