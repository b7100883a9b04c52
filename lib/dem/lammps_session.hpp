// One embedded LAMMPS instance (Debian liblammps, GRANULAR package) on an
// MPI communicator, driven through its documented C library API. Every
// command goes through command(), which keeps it, so the exact input a
// run sent can be written to the output folder (dem_commands.txt) and
// replayed with LAMMPS's own executable. This build of LAMMPS aborts the
// process on an input error: callers send only commands made from
// validated project structs.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace frostwall::dem {

// MPI started if nobody has (finalised at exit); this process's rank in
// MPI_COMM_WORLD; a barrier there.
void ensure_mpi();
int world_rank();
void world_barrier();

class LammpsSession {
 public:
  // On MPI_COMM_WORLD; initialises MPI if nobody has (one rank without
  // mpirun). LAMMPS writes nothing to the screen, and its log (where it
  // explains an abort) to `log_file`, or nowhere when that is empty.
  explicit LammpsSession(const std::string& log_file = "");
  ~LammpsSession();
  LammpsSession(const LammpsSession&) = delete;
  LammpsSession& operator=(const LammpsSession&) = delete;

  void command(const std::string& line);
  const std::vector<std::string>& commands() const { return commands_; }
  // Runs n steps (no set-up output; the forces are rebuilt at the start).
  void run(long steps);

  // This rank's grains (LAMMPS's per-atom arrays; valid until the next
  // command or run): how many, ids, positions, velocities, radii, and each
  // grain's contact count (compute `contacts`, contact_commands()).
  int local_count() const;
  int* ids() const;
  double** position() const;
  double** velocity() const;
  double* radius() const;
  double* contacts() const;
  // Grains in the whole assembly (all ranks).
  long grain_count() const;
  // The simulated time so far (s; LAMMPS' `time`).
  double time() const;
  int rank() const { return rank_; }
  int ranks() const { return ranks_; }

  // A force added to every local grain each step through `fix external`
  // (the fix must have been made with command(), pf/callback): f(n, x, F)
  // fills F[i][0..2] in newtons for the n local grains with these ids at
  // positions x.
  using ForceFunction = std::function<void(int n, const int* ids, double** x, double** force)>;
  void set_external_force(const std::string& fix_id, ForceFunction f);

 private:
  static void callback(void* self, std::int64_t step, int n, int* ids, double** x, double** force);
  void* lammps_ = nullptr;
  int rank_ = 0, ranks_ = 1;
  std::vector<std::string> commands_;
  ForceFunction force_;
};

}  // namespace frostwall::dem
