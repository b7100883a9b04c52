#include "dem/packing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>
#include <numbers>
#include <random>

#include "project/project.hpp"

namespace frostwall::dem {

namespace {

// The generator's raw output to [0, 1): the same on every platform
// (std::uniform_real_distribution is not).
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

}  // namespace

double mean_grain_volume(const project::GrainSettings& g) {
  const double a = g.diameter_min, b = g.diameter_max;
  const double mean_d3 = b > a ? (std::pow(b, 4) - std::pow(a, 4)) / (4.0 * (b - a)) : a * a * a;
  return std::numbers::pi / 6.0 * mean_d3;
}

double mean_grain_diameter(const project::GrainSettings& g) {
  return std::cbrt(6.0 / std::numbers::pi * mean_grain_volume(g));
}

double fill_volume(const project::CfdDem& c) {
  auto g = c.grains;
  for (int k = 0; k < 3; ++k)
    g.fill_high[k] = std::min(g.fill_high[k], c.box.high[k]);  // a settling column counts to the top
  double volume = 1.0;
  for (int k = 0; k < 3; ++k) volume *= g.fill_high[k] - g.fill_low[k];
  if (!c.cavity) return volume;
  // The cavity's share of the fill region, on a 64^3 midpoint grid.
  const int n = 64;
  long inside = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const std::array<double, 3> x = {g.fill_low[0] + (i + 0.5) / n * (g.fill_high[0] - g.fill_low[0]),
                                         g.fill_low[1] + (j + 0.5) / n * (g.fill_high[1] - g.fill_low[1]),
                                         g.fill_low[2] + (k + 0.5) / n * (g.fill_high[2] - g.fill_low[2])};
        inside += in_cavity(c, x.data());
      }
  return volume * (1.0 - static_cast<double>(inside) / (static_cast<double>(n) * n * n));
}

long requested_grains(const project::CfdDem& c) {
  if (c.grains.count) return *c.grains.count;
  return std::max(1L,
                  std::lround((1.0 - c.grains.porosity.value_or(1.0)) * fill_volume(c) / mean_grain_volume(c.grains)));
}

std::vector<Grain> initial_grains(const project::CfdDem& c) {
  const auto& g = c.grains;
  const long wanted = requested_grains(c);
  // Lattice spacing: 10 % above the largest grain, so jittered neighbours
  // never touch; held grains: even over the region.
  const double spacing = g.held ? std::cbrt(fill_volume(c) / wanted) : 1.1 * g.diameter_max;
  const double jitter = g.held ? 0.0 : 0.5 * (spacing - g.diameter_max) * 0.9;
  std::array<int, 3> n{};
  for (int k = 0; k < 3; ++k) {
    const double length = g.fill_high[k] - g.fill_low[k];
    if (g.held) {
      n[k] = std::max(1, static_cast<int>(std::lround(length / spacing)));
      continue;
    }
    // A periodic axis wraps: its sites fill the whole length.
    n[k] = c.box.periodic[k] ? std::max(1, static_cast<int>(std::floor(length / spacing)))
                             : std::max(1, static_cast<int>(std::floor((length - g.diameter_max) / spacing)) + 1);
  }
  // A held bed: enough sites for every grain, one more layer where the
  // sites are sparsest if rounding left too few.
  while (g.held && static_cast<long>(n[0]) * n[1] * n[2] < wanted) {
    int sparse = 0;
    for (int k = 1; k < 3; ++k)
      if ((g.fill_high[k] - g.fill_low[k]) / n[k] > (g.fill_high[sparse] - g.fill_low[sparse]) / n[sparse]) sparse = k;
    ++n[sparse];
  }
  std::vector<std::array<double, 3>> sites;
  for (int i = 0; i < n[0]; ++i)
    for (int j = 0; j < n[1]; ++j)
      for (int k = 0; k < n[2]; ++k) {
        const std::array<int, 3> ijk = {i, j, k};
        std::array<double, 3> x{};
        for (int a = 0; a < 3; ++a) {
          const double length = g.fill_high[a] - g.fill_low[a];
          const double pitch = length / n[a];  // evenly spread over the axis
          x[a] = g.fill_low[a] + (ijk[a] + 0.5) * pitch;
        }
        if (!in_cavity(c, x.data(), 0.5 * g.diameter_max)) sites.push_back(x);
      }
  if (static_cast<long>(sites.size()) < wanted) {
    const char* key = g.count ? "grains.count" : "grains.porosity";
    throw project::ProjectError({fmt::format(
        "{}: {} grains do not fit apart in the fill region ({} lattice sites of {:.3g} m); enlarge grains.fill "
        "upward (they settle) or ask for fewer",
        key, wanted, sites.size(), spacing)});
  }
  // Held: every (sites / wanted)-th site, spread over the whole region.
  if (g.held && static_cast<long>(sites.size()) > wanted) {
    std::vector<std::array<double, 3>> spread;
    for (long i = 0; i < wanted; ++i)
      spread.push_back(sites[static_cast<std::size_t>(i * double(sites.size()) / wanted)]);
    sites = std::move(spread);
  }
  // Bottom first: sites lowest along gravity (then by position, a total order).
  const auto& gv = c.gravity;
  std::stable_sort(sites.begin(), sites.end(), [&](const auto& a, const auto& b) {
    const double ha = -(a[0] * gv[0] + a[1] * gv[1] + a[2] * gv[2]), hb = -(b[0] * gv[0] + b[1] * gv[1] + b[2] * gv[2]);
    return ha < hb - 1e-12 * spacing;
  });
  std::mt19937_64 rng(g.seed);
  std::vector<Grain> grains;
  grains.reserve(wanted);
  for (long i = 0; i < wanted; ++i) {
    Grain grain;
    grain.diameter = g.diameter_min + (g.diameter_max - g.diameter_min) * unit(rng);
    grain.density = g.density;
    for (int k = 0; k < 3; ++k) grain.position[k] = sites[i][k] + jitter * (2.0 * unit(rng) - 1.0);
    grains.push_back(grain);
  }
  return grains;
}

bool in_cavity(const project::CfdDem& c, const double* x, double clearance) {
  if (!c.cavity) return false;
  double r2 = 0.0;
  for (int k = 0; k < 3; ++k) r2 += (x[k] - c.cavity->centre[k]) * (x[k] - c.cavity->centre[k]);
  return r2 < (c.cavity->radius + clearance) * (c.cavity->radius + clearance);
}

std::pair<std::array<double, 3>, std::array<double, 3>> heap_container(const project::CfdDem& c) {
  auto high = c.grains.fill_high;
  high[2] = c.box.high[2];
  return {c.grains.fill_low, high};
}

std::filesystem::path packing_cache_file(const project::CfdDem& c, double timestep, int interval) {
  const auto& g = c.grains;
  std::string key = fmt::format("v1 {} {} {} {} {} {} {} {} {} {} {} {}", g.diameter_min, g.diameter_max, g.density,
                                g.youngs_modulus, g.poisson_ratio, g.restitution, g.friction, g.rolling_friction,
                                requested_grains(c), g.seed, g.settle_time, g.held);
  if (g.settle_friction) key += fmt::format(" settle_friction {}", *g.settle_friction);
  for (int k = 0; k < 3; ++k)
    key += fmt::format(" {} {} {} {} {} {} {}", g.fill_low[k], g.fill_high[k], c.box.low[k], c.box.high[k],
                       c.box.periodic[k], c.gravity[k], c.fluid.cells[k]);
  if (c.cavity)
    key += fmt::format(" cavity {} {} {} {}", c.cavity->centre[0], c.cavity->centre[1], c.cavity->centre[2],
                       c.cavity->radius);
  if (c.heap) key += " heap container";
  key += fmt::format(" {} {} {} {} {}", c.fluid.density, c.fluid.viscosity, c.fluid.min_porosity, timestep, interval);
  for (const auto& f : c.forces) key += " " + f;
  // The drag's coupling shapes a packing that settles under the grid (a
  // settling column feels only buoyancy).
  if (!has_settling_column(c))
    key += c.coupling.drag == project::DragCoupling::semi_implicit ? " semi-implicit drag" : " explicit drag";
  std::uint64_t hash = 1469598103934665603ULL;  // FNV-1a
  for (unsigned char ch : key) hash = (hash ^ ch) * 1099511628211ULL;
  std::filesystem::path dir;
  if (const char* d = std::getenv("FROSTWALL_CACHE"); d && *d) dir = d;
  else if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) dir = std::filesystem::path(x) / "frostwall";
  else if (const char* h = std::getenv("HOME"); h && *h) dir = std::filesystem::path(h) / ".cache" / "frostwall";
  else dir = std::filesystem::temp_directory_path() / "frostwall-cache";
  return dir / fmt::format("packing-{:016x}.restart", hash);
}

Box dem_box(const project::CfdDem& c) { return {c.box.low, c.box.high, c.box.periodic}; }

bool has_settling_column(const project::CfdDem& c) { return c.grains.fill_high[2] > c.box.high[2]; }

Box settling_box(const project::CfdDem& c) {
  Box box = dem_box(c);
  box.high[2] = std::max(box.high[2], c.grains.fill_high[2]);
  return box;
}

Contact dem_contact(const project::CfdDem& c) {
  const auto& g = c.grains;
  Contact contact{g.youngs_modulus, g.poisson_ratio, g.restitution, g.friction, g.rolling_friction, 0.0};
  // Rolling stiffness of the order of the normal contact stiffness at a
  // contact radius of 1/20 of the grain: E d / 20.
  contact.rolling_stiffness = g.youngs_modulus * g.mean_diameter() / 20.0;
  return contact;
}

}  // namespace frostwall::dem
