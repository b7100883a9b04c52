// The pores of a porous plate and the fluid in them (load_pores.hpp).
// lib/CMakeLists.txt compiles this file with -ffp-contract=off, so that no
// compiler fuses a multiply and an add in draw_pores: the same seed must
// draw the same pores on every platform.
#include "project/load_pores.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include <fmt/format.h>

namespace frostwall::project::detail {

namespace {

constexpr int tries_per_pore = 10000;

// [0, 1) from the generator's raw 64 bits (the top 53 as the mantissa):
// std::uniform_real_distribution is not the same in every standard library.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

bool inside(const Pore& p, double width, double height, double gap) {
  return p.x - p.radius >= gap && p.x + p.radius + gap <= width && p.y - p.radius >= gap &&
         p.y + p.radius + gap <= height;
}

// Two discs at least `gap` apart (touching when gap is 0). Squares only,
// which round the same everywhere (std::hypot need not).
bool apart(const Pore& a, const Pore& b, double gap) {
  const double dx = a.x - b.x, dy = a.y - b.y, reach = a.radius + b.radius + gap;
  return dx * dx + dy * dy >= reach * reach;
}

// A non-negative integer (the generator's seed).
std::optional<unsigned long long> seed_of(const Node& n) {
  if (!n.given()) return std::nullopt;
  const Json& v = n.json();
  if (!v.is_number_unsigned()) {  // nlohmann reads every integer >= 0 as unsigned
    n.problem("must be a non-negative integer, got " + (v.is_number() ? n.shown() : n.type()));
    return std::nullopt;
  }
  return v.get<unsigned long long>();
}

// A degree of saturation: a number in (0, 1].
std::optional<double> saturation_of(const Node& n) {
  const auto S = n.number();
  if (!S) return std::nullopt;
  if (!(*S > 0.0 && *S <= 1.0)) {
    n.problem(fmt::format("must be in (0, 1] (the share of the pore's volume the water fills), got {}", n.shown()));
    return std::nullopt;
  }
  return S;
}

// "saturation" of a generator: a number S (every pore S) or [min, max],
// 0 < min <= max <= 1.
std::optional<std::pair<double, double>> saturation_range(const Node& n) {
  if (n.json().is_array()) {
    if (n.json().size() != 2) {
      n.problem(fmt::format("must be a number or [min, max], got {}", n.shown()));
      return std::nullopt;
    }
    const auto lo = saturation_of(n[0]), hi = saturation_of(n[1]);
    if (!lo || !hi) return std::nullopt;
    if (*lo > *hi) {
      n.problem(fmt::format("must be [min, max] with min <= max, got {}", n.shown()));
      return std::nullopt;
    }
    return std::pair{*lo, *hi};
  }
  const auto S = saturation_of(n);
  return S ? std::optional{std::pair{*S, *S}} : std::nullopt;
}

// "radius": a number r (every pore r) or [min, max], 0 < min <= max.
std::optional<std::pair<double, double>> radius_range(const Node& n) {
  if (!n.given()) return std::nullopt;
  if (n.json().is_number()) {
    const auto r = n.positive();
    return r ? std::optional{std::pair{*r, *r}} : std::nullopt;
  }
  if (!n.json().is_array() || n.json().size() != 2) {
    n.problem("must be a radius or [min, max] in metres, got " + (n.json().is_array() ? n.shown() : n.type()));
    return std::nullopt;
  }
  const auto lo = n[0].positive(), hi = n[1].positive();
  if (!lo || !hi) return std::nullopt;
  if (*lo > *hi) {
    n.problem(fmt::format("must be [min, max] with min <= max, got {}", n.shown()));
    return std::nullopt;
  }
  return std::pair{*lo, *hi};
}

void read_generator(const Node& n, Rectangle& rectangle, double plate_saturation) {
  n.object({"count", "radius", "min_gap", "seed", "saturation"});
  const Node count_node = n["count"].required();
  const auto count = count_node.count();
  const auto radius = radius_range(n["radius"].required());
  const auto gap = n["min_gap"].present() ? n["min_gap"].non_negative() : std::optional{0.0};
  const auto seed = n["seed"].present() ? seed_of(n["seed"]) : std::optional{1ULL};
  const auto saturation = n["saturation"].present() ? saturation_range(n["saturation"])
                                                    : std::optional{std::pair{plate_saturation, plate_saturation}};
  if (!count || !radius || !gap || !seed || !saturation) return;
  const PoreGenerator g{*count, radius->first, radius->second, *gap, *seed, saturation->first, saturation->second};
  rectangle.pore_generator = g;
  if (!(rectangle.width > 0) || !(rectangle.height > 0)) return;  // reported with the width or height
  rectangle.pores = draw_pores(g, rectangle.width, rectangle.height);
  if (static_cast<int>(rectangle.pores.size()) < g.count) {
    const std::string radii = g.radius_min == g.radius_max ? fmt::format("{}", g.radius_min)
                                                           : fmt::format("{}..{}", g.radius_min, g.radius_max);
    count_node.problem(
        fmt::format("cannot place {} pores of radius {} m at least {} m apart inside the plate (placed {})", g.count,
                    radii, g.min_gap, rectangle.pores.size()));
  }
}

void read_list(const Node& n, Rectangle& rectangle, double plate_saturation) {
  const std::size_t size = n.array().value_or(0);
  if (size == 0) {
    n.problem(R"(must list at least one pore (leave "pores" out for a plate without pores))");
    return;
  }
  const bool plate_known = rectangle.width > 0 && rectangle.height > 0;
  std::vector<std::size_t> index;  // of each pore read, in n
  for (std::size_t i = 0; i < size; ++i) {
    const Node p = n[i];
    if (!p.object({"x", "y", "radius", "saturation"})) continue;
    const auto x = p["x"].required().number(), y = p["y"].required().number();
    const auto r = p["radius"].required().positive();
    const auto S = p["saturation"].present() ? saturation_of(p["saturation"]) : std::optional{plate_saturation};
    if (!x || !y || !r || !S) continue;
    const Pore pore{*x, *y, *r, *S};
    if (plate_known && !inside(pore, rectangle.width, rectangle.height, 0.0)) {
      p.problem(fmt::format("the pore (x {}, y {}, radius {}) is not inside the {} x {} m plate", pore.x, pore.y,
                            pore.radius, rectangle.width, rectangle.height));
      continue;
    }
    for (std::size_t j = 0; j < rectangle.pores.size(); ++j)
      if (!apart(pore, rectangle.pores[j], 0.0)) p.problem("overlaps " + n[index[j]].path());
    rectangle.pores.push_back(pore);
    index.push_back(i);
  }
}

}  // namespace

std::vector<Pore> draw_pores(const PoreGenerator& g, double width, double height) {
  std::vector<Pore> pores;
  if (g.count < 1 || !(width > 0) || !(height > 0)) return pores;
  std::mt19937_64 rng(g.seed);
  const double gap = g.min_gap;
  // Two pores can only conflict with centres closer than 2 radius_max + gap:
  // with cells at least that wide a candidate is checked against the pores
  // of its own cell and of the eight around it.
  const double cell = std::max(2 * g.radius_max + gap, std::max(width, height) * 1e-9);
  const auto key = [](std::int64_t ix, std::int64_t iy) { return (ix << 32) + iy; };
  const auto cell_of = [&](double v) { return static_cast<std::int64_t>(v / cell); };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  const auto fits = [&](const Pore& p) {
    if (!inside(p, width, height, gap)) return false;  // exactly, whatever the rounding of the draw
    const std::int64_t ix = cell_of(p.x), iy = cell_of(p.y);
    for (std::int64_t i = ix - 1; i <= ix + 1; ++i)
      for (std::int64_t j = iy - 1; j <= iy + 1; ++j)
        if (const auto it = cells.find(key(i, j)); it != cells.end())
          for (const std::size_t other : it->second)
            if (!apart(p, pores[other], gap)) return false;
    return true;
  };
  for (int k = 0; k < g.count; ++k) {
    Pore p;
    p.radius = g.radius_min + (g.radius_max - g.radius_min) * unit(rng);
    const double margin = p.radius + gap;  // the centre's distance from every side
    if (width < 2 * margin || height < 2 * margin) return pores;
    bool placed = false;
    for (int t = 0; t < tries_per_pore && !placed; ++t) {
      p.x = margin + (width - 2 * margin) * unit(rng);
      p.y = margin + (height - 2 * margin) * unit(rng);
      placed = fits(p);
    }
    if (!placed) return pores;
    cells[key(cell_of(p.x), cell_of(p.y))].push_back(pores.size());
    pores.push_back(p);
  }
  // The saturations from a stream of their own: a range moves no pore.
  std::mt19937_64 wet(g.seed ^ 0x5a7u);
  for (auto& p : pores)
    p.saturation = g.saturation_min == g.saturation_max
                       ? g.saturation_min
                       : g.saturation_min + (g.saturation_max - g.saturation_min) * unit(wet);
  return pores;
}

void read_pores(const Node& n, Rectangle& rectangle, const Node& plate_saturation) {
  if (!n.present()) {
    if (plate_saturation.present()) plate_saturation.problem("the plate has no pores (geometry.pores)");
    return;
  }
  const double S = plate_saturation.present() ? saturation_of(plate_saturation).value_or(1.0) : 1.0;
  if (n.json().is_array()) return read_list(n, rectangle, S);
  if (n.json().is_object()) return read_generator(n, rectangle, S);
  n.problem(R"(must be a list of pores [{"x", "y", "radius"}, ...] or a generator {"count", "radius", ...}, got )" +
            n.type());
}

PoreFluid read_pore_fluid(const Node& n) {
  PoreFluid fluid;
  if (!n.object({"water", "ice", "latent_heat", "freezing_point"})) return fluid;
  for (const auto& [key, conductivity, heat_capacity, density] :
       {std::tuple{"water", &fluid.water_conductivity, &fluid.water_heat_capacity, &fluid.water_density},
        std::tuple{"ice", &fluid.ice_conductivity, &fluid.ice_heat_capacity, &fluid.ice_density}}) {
    const Node phase = n[key];
    if (!phase.object({"conductivity", "heat_capacity", "density"})) continue;
    *conductivity = phase["conductivity"].positive().value_or(*conductivity);
    *heat_capacity = phase["heat_capacity"].positive().value_or(*heat_capacity);
    *density = phase["density"].positive().value_or(*density);
  }
  fluid.latent_heat = n["latent_heat"].non_negative().value_or(fluid.latent_heat);
  fluid.freezing_point = n["freezing_point"].number().value_or(fluid.freezing_point);
  return fluid;
}

void read_pore_settings(const Node& root, Project& project) {
  const bool pores = std::holds_alternative<Rectangle>(project.geometry) && root["geometry"]["pores"].present();
  if (const Node fluid = root["pore_fluid"]; fluid.present()) {
    project.pore_fluid = read_pore_fluid(fluid);
    if (!pores) project.warnings.push_back("pore_fluid: the plate has no pores (geometry.pores); ignored");
  }
  if (!project.mechanics) return;
  if (pores && !project.mechanics->freezing_expansion) project.mechanics->freezing_expansion = FreezingExpansion{};
  if (const Node expansion = root["mechanics"]["freezing_expansion"]; !pores && expansion.present())
    expansion.problem("the plate has no pores (geometry.pores)");
}

}  // namespace frostwall::project::detail
