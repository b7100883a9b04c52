// The one place that decides how particle loops run (OpenMP, static
// schedule). Physics code calls for_each_particle and never writes threading.
#pragma once

#include <cstddef>

namespace frostwall::sph {

template <class Body>
void for_each_particle(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
}

// Sum over particles of body(i), reduced across threads.
template <class Body>
double sum_over_particles(std::size_t n, Body&& body) {
  const long long count = static_cast<long long>(n);
  double total = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : total)
  for (long long i = 0; i < count; ++i) total += body(static_cast<std::size_t>(i));
  return total;
}

}  // namespace frostwall::sph
