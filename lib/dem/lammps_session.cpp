#include "dem/lammps_session.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <mpi.h>
#include <stdexcept>
// The API's MPI form and its integer sizes as this build was compiled
// (LAMMPS_SMALLBIG comes from the LAMMPS::lammps CMake target).
#define LAMMPS_LIB_MPI
#include <lammps/library.h>

namespace frostwall::dem {

namespace {

// LAMMPS as Debian builds it (no C++ exceptions: lammps_config_has_exceptions
// is 0) ends the process on an input error: exit(1) after writing "ERROR: ..."
// to its log. The open session's log is remembered, and at such an exit its
// ERROR line goes to stderr as the run's one line. (An error LAMMPS finds on
// one rank only calls MPI_Abort, which runs no exit handler.)
std::string open_log;
int open_rank = 0;

void report_lammps_exit() {
  if (open_log.empty() || open_rank != 0) return;
  std::ifstream in(open_log);
  std::string error;
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("ERROR")) error = line;
  if (error.empty()) error = "stopped without an ERROR line";
  std::fprintf(stderr, "frostwall: run failed: LAMMPS %s (%s)\n", error.c_str(), open_log.c_str());
}

}  // namespace

void ensure_mpi() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised) return;
  MPI_Init(nullptr, nullptr);
  // Finalised once, at exit, however many sessions a process made.
  std::atexit([] {
    int finalised = 0;
    MPI_Finalized(&finalised);
    if (!finalised) MPI_Finalize();
  });
}

int world_rank() {
  ensure_mpi();
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

void world_barrier() { MPI_Barrier(MPI_COMM_WORLD); }

LammpsSession::LammpsSession(const std::string& log_file) {
  ensure_mpi();
  const std::string log = log_file.empty() ? "none" : log_file;
  const char* args[] = {"frostwall", "-log", log.c_str(), "-screen", "none", "-nocite"};
  lammps_ = lammps_open(6, const_cast<char**>(args), MPI_COMM_WORLD, nullptr);
  if (!lammps_) throw std::runtime_error("LAMMPS could not be started");
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
  static const bool registered = std::atexit(report_lammps_exit) == 0;
  if (registered && !log_file.empty()) open_log = log_file, open_rank = rank_;
}

LammpsSession::~LammpsSession() {
  open_log.clear();
  if (lammps_) lammps_close(lammps_);
}

void LammpsSession::command(const std::string& line) {
  commands_.push_back(line);
  lammps_command(lammps_, line.c_str());
}

void LammpsSession::run(long steps) { command("run " + std::to_string(steps) + " pre no post no"); }

int LammpsSession::local_count() const { return lammps_extract_setting(lammps_, "nlocal"); }
int* LammpsSession::ids() const { return static_cast<int*>(lammps_extract_atom(lammps_, "id")); }
double** LammpsSession::position() const { return static_cast<double**>(lammps_extract_atom(lammps_, "x")); }
double** LammpsSession::velocity() const { return static_cast<double**>(lammps_extract_atom(lammps_, "v")); }
double* LammpsSession::radius() const { return static_cast<double*>(lammps_extract_atom(lammps_, "radius")); }
double* LammpsSession::contacts() const {
  return static_cast<double*>(lammps_extract_compute(lammps_, "contacts", LMP_STYLE_ATOM, LMP_TYPE_VECTOR));
}
double LammpsSession::time() const { return lammps_get_thermo(lammps_, "time"); }

long LammpsSession::grain_count() const { return std::lround(lammps_get_natoms(lammps_)); }

void LammpsSession::set_external_force(const std::string& fix_id, ForceFunction f) {
  force_ = std::move(f);
  lammps_set_fix_external_callback(lammps_, fix_id.c_str(), &LammpsSession::callback, this);
}

void LammpsSession::callback(void* self, std::int64_t, int n, int* ids, double** x, double** force) {
  auto* session = static_cast<LammpsSession*>(self);
  if (session->force_) session->force_(n, ids, x, force);
}

}  // namespace frostwall::dem
