// The one place that decides how particle loops run (OpenMP, static
// schedule). Physics code calls for_each_particle and never writes threading.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <omp.h>
#include <xmmintrin.h>

namespace frostwall::particles {

// Below this many particles a loop runs on one thread: the fork/join of a
// parallel region would cost more than the work, and with more threads
// than free cores (ctest -j, a study) spinning threads stall each other.
inline constexpr std::size_t parallel_threshold = 4096;

template <class Body>
void for_each_particle(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static) if (n >= parallel_threshold)
  for (long long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
}

// Runs body() with OpenMP (and so OpenBLAS, which follows OpenMP's thread
// count) on one thread: for library calls made of many small BLAS-2
// operations (a sparse triangular solve), where forking a team for each
// costs more than it saves. No parallel region inside is active, also
// those that ask for a thread count of their own: CHOLMOD's supernodal
// factorization forks 4 threads (its compiled-in CHOLMOD_OMP_NUM_THREADS)
// to clear each supernode: on a machine with fewer cores, much of a run's
// time goes to waking and parking threads (bench/README.md, "Solver levers").
template <class Body>
decltype(auto) serially(Body&& body) {
  struct Restore {
    int threads = omp_get_max_threads();
    int levels = omp_get_max_active_levels();
    ~Restore() {
      omp_set_num_threads(threads);
      omp_set_max_active_levels(levels);
    }
  } restore;
  omp_set_num_threads(1);
  omp_set_max_active_levels(0);
  return body();
}

// A few items of much work each (the rays of a fan): shared among the
// threads whatever their count, each taking the next free item.
template <class Body>
void for_each_item(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(dynamic)
  for (long long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
}

// Sum over particles of body(i), reduced across threads.
template <class Body>
double sum_over_particles(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
  double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total) if (n >= parallel_threshold)
  for (long long i = 0; i < count; ++i) total += body(static_cast<std::size_t>(i));
  return total;
}

// Several sums in one pass: body(i, acc) adds particle i's terms to acc
// (K values); one fork/join instead of K (the relaxation needs four per
// iteration).
template <std::size_t K, class Body>
std::array<double, K> sums_over_particles(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
  std::array<double, K> total{};
#pragma omp parallel if (n >= parallel_threshold)
  {
    std::array<double, K> local{};
#pragma omp for schedule(static) nowait
    for (long long i = 0; i < count; ++i) body(static_cast<std::size_t>(i), local);
#pragma omp critical
    for (std::size_t k = 0; k < K; ++k) total[k] += local[k];
  }
  return total;
}

// Largest body(i) over particles (0 for none), reduced across threads.
template <class Body>
double max_over_particles(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
  double largest = 0.0;
#pragma omp parallel for schedule(static) reduction(max : largest) if (n >= parallel_threshold)
  for (long long i = 0; i < count; ++i) largest = std::max(largest, body(static_cast<std::size_t>(i)));
  return largest;
}

// Flush denormal numbers to zero in this thread and every OpenMP thread.
// Far ahead of a cooling front the temperature perturbation decays through
// 1e-308 into denormals, which x86 handles far more slowly than normal
// numbers; they carry no physics (bench/README.md, "Denormals").
inline void flush_denormals_to_zero() {
  constexpr unsigned ftz_daz = 0x8040;  // MXCSR flush-to-zero | denormals-are-zero
  _mm_setcsr(_mm_getcsr() | ftz_daz);
#pragma omp parallel
  _mm_setcsr(_mm_getcsr() | ftz_daz);
}

}  // namespace frostwall::particles
