// Seconds per call of f, timed over about a second after one warm-up call
// (the benchmark executables share it).
#pragma once

#include <chrono>

namespace frostwall::bench {

template <class F>
double seconds_per_call(F&& f) {
  f();
  int calls = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  while (elapsed < 1.0) {
    f();
    ++calls;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return elapsed / calls;
}

}  // namespace frostwall::bench
