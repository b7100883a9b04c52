// Whole tasks (runs of a study, forward runs of a calibration) shared
// among a few threads of their own, each task's particle loops on its own
// OpenMP threads.
#pragma once

#include <cstddef>
#include <functional>

namespace frostwall::particles {

// Runs task(0) .. task(count - 1), `jobs` at a time (at most count, at
// least 1), each worker taking the next free task and running its OpenMP
// loops on `threads` threads (at least 1). With one job the tasks run on
// the caller's thread, whose OpenMP thread count is restored afterwards.
// A task that throws does not stop the others; once all have run, the
// first failure is rethrown on the caller's thread.
void side_by_side(std::size_t count, int jobs, int threads, const std::function<void(std::size_t)>& task);

// The cores whole tasks may share: the machine's processors, or fewer when
// the environment's OMP_NUM_THREADS says so (as a batch system or a test
// runner that runs several programs at once sets it). At least 1.
int usable_cores();

}  // namespace frostwall::particles
