#include "particles/side_by_side.hpp"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <omp.h>
#include <thread>
#include <vector>

namespace frostwall::particles {

int usable_cores() {
  int cores = std::max(1, omp_get_num_procs());
  if (const char* limit = std::getenv("OMP_NUM_THREADS"); limit && *limit) {
    char* end = nullptr;
    const long n = std::strtol(limit, &end, 10);
    if (end != limit && n > 0) cores = static_cast<int>(std::min<long>(n, cores));
  }
  return cores;
}

void side_by_side(std::size_t count, int jobs, int threads, const std::function<void(std::size_t)>& task) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_lock;
  auto worker = [&] {
    omp_set_num_threads(std::max(1, threads));  // this thread's own setting
    for (std::size_t i; (i = next++) < count;) {
      try {
        task(i);
      } catch (...) {
        std::lock_guard lock(failure_lock);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const int n = std::clamp(jobs, 1, std::max(1, static_cast<int>(count)));
  if (n == 1) {
    const int saved = omp_get_max_threads();
    worker();
    omp_set_num_threads(saved);
  } else {
    std::vector<std::thread> pool;
    for (int j = 0; j < n; ++j) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace frostwall::particles
