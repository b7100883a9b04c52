// Pair-update rate of the conduction kernel (ThermalModel::conduction_rate)
// on the main case's particles, against a plain CSR gather over the same
// pairs with stored weights, timed in the same process (the machine is
// shared and noisy: the ratio is the number to trust), on 1 and 2 threads.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <omp.h>
#include <vector>

#include "project/project.hpp"
#include "timing.hpp"
#include "freezing/model.hpp"

using namespace frostwall;
using frostwall::bench::seconds_per_call;

int main() {
  project::Project p = project::load_project(FROSTWALL_SOURCE_DIR "/projects/single_ring_sand.json");
  p.numerics.integrator = project::IntegratorKind::explicit_euler;
  p.numerics.spacing = 0.025;
  p.numerics.placement = project::Placement::lattice;  // paper mode's cloud
  freezing::Model m = freezing::build_model(p);
  const auto& model = *m.model;
  const auto& P = model.pairs();
  const std::size_t n = P.n_free, pairs = P.pairs();
  std::vector<double> rate, x(model.size(), 1.0), y(n);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = model.temperature()[i] + 1e-3 * double(i % 17);

  std::printf("  %zu particles, %zu pairs\n", n, pairs);
  // The first engine's loop: the harmonic mean 4 k_i k_j / (k_i + k_j)
  // computed in the loop for every pair (a division per pair), instead of
  // coefficients cached and refreshed only next to freezing particles.
  std::vector<double> k(model.size());
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = model.conductivity(i, 0);
  omp_set_num_threads(1);
  const double inline_mean = seconds_per_call([&] {
    for (std::size_t i = 0; i < n; ++i) {
      const double Ti = x[i], ki = k[i];
      double sum = 0.0;
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
        const std::uint32_t j = P.column[e];
        sum += P.weight[e] * (4.0 * ki * k[j] / (ki + k[j])) * (x[j] - Ti);
      }
      y[i] = sum;
    }
  });
  const double cached = seconds_per_call([&] { model.conduction_rate(rate); });
  std::printf(
      "  1 thread: harmonic mean per pair in the loop %.2e pairs/s; cached coefficients %.2e pairs/s (%.2fx)\n\n",
      pairs / inline_mean, pairs / cached, inline_mean / cached);
  std::printf("  threads  conduction_rate     plain CSR gather    kernel / gather\n");
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const double kernel = seconds_per_call([&] { model.conduction_rate(rate); });
    const double gather = seconds_per_call([&] {
      const long long count = static_cast<long long>(n);
#pragma omp parallel for schedule(static)
      for (long long i = 0; i < count; ++i) {
        double sum = 0.0;
        for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) sum += P.weight[e] * x[P.column[e]];
        y[i] = sum;
      }
    });
    std::printf("  %-7d  %.2e pairs/s    %.2e pairs/s    %.2f\n", threads, pairs / kernel, pairs / gather,
                gather / kernel);
  }

  // Memory order: the lattice is built row by row (neighbours a few rows
  // apart); compare the plain gather in that order, in Morton (Z) order of
  // the cell, and in a random order (what an unsorted cloud would cost).
  omp_set_num_threads(1);
  const auto& X = m.particles().position;
  auto gather_in = [&](const std::vector<std::size_t>& order) {
    std::vector<std::size_t> rank(model.size());
    for (std::size_t k = 0; k < model.size(); ++k) rank[order[k]] = k;
    std::vector<std::size_t> start{0};
    std::vector<std::uint32_t> col;
    std::vector<double> w;
    for (std::size_t k = 0; k < model.size(); ++k) {
      const std::size_t i = order[k];
      if (i < n)
        for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
          col.push_back(static_cast<std::uint32_t>(rank[P.column[e]]));
          w.push_back(P.weight[e]);
        }
      start.push_back(col.size());
    }
    std::vector<double> xs(model.size()), ys(model.size());
    for (std::size_t k = 0; k < model.size(); ++k) xs[k] = x[order[k]];
    return seconds_per_call([&] {
      for (std::size_t k = 0; k < model.size(); ++k) {
        double sum = 0.0;
        for (std::size_t e = start[k]; e < start[k + 1]; ++e) sum += w[e] * xs[col[e]];
        ys[k] = sum;
      }
    });
  };
  std::vector<std::size_t> built(model.size()), morton(model.size()), shuffled(model.size());
  for (std::size_t i = 0; i < model.size(); ++i) built[i] = morton[i] = shuffled[i] = i;
  const double cell = 2.0 * m.h;
  auto code = [&](std::size_t i) {
    const auto ix = static_cast<std::uint32_t>((X[i][0] + 100.0) / cell),
               iy = static_cast<std::uint32_t>((X[i][1] + 100.0) / cell);
    std::uint64_t c = 0;
    for (int b = 0; b < 16; ++b)
      c |= (std::uint64_t((ix >> b) & 1u) << (2 * b)) | (std::uint64_t((iy >> b) & 1u) << (2 * b + 1));
    return c;
  };
  std::stable_sort(morton.begin(), morton.end(), [&](std::size_t a, std::size_t b) { return code(a) < code(b); });
  std::uint64_t state = 12345;
  for (std::size_t k = shuffled.size(); k > 1; --k) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    std::swap(shuffled[k - 1], shuffled[(state >> 33) % k]);
  }
  const double t_built = gather_in(built), t_morton = gather_in(morton), t_random = gather_in(shuffled);
  std::printf("\n  memory order (plain gather, 1 thread): as built (rows) %.2e pairs/s, Morton %.2e pairs/s (%.2fx), "
              "random %.2e pairs/s (%.2fx)\n",
              pairs / t_built, pairs / t_morton, t_built / t_morton, pairs / t_random, t_built / t_random);
  return 0;
}
