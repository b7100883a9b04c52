#include "cfd_dem/stability.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <mpi.h>

namespace frostwall::cfd_dem {

namespace {

// The water's fastest interstitial speed on the grid (m/s).
double fastest_water(const pore_water::FluidGrid& grid) {
  const auto U = grid.superficial_velocity();
  const auto& eps = grid.porosity();
  double fastest = 0.0;
  for (std::size_t i = 0; i < U.size(); ++i) fastest = std::max(fastest, U[i].norm() / std::max(eps[i], 1e-3));
  return fastest;
}

}  // namespace

StabilityWatch::StabilityWatch(const project::CfdDem& c, double dt, int interval)
    : c_(c), dt_(dt), interval_(interval), given_(c.coupling.interval.has_value()) {
  // The box's height along gravity (its largest extent without gravity's direction).
  const double g = std::hypot(c.gravity[0], c.gravity[1], c.gravity[2]);
  const int axis = project::gravity_axis(c);
  double height = 0.0;
  for (int k = 0; k < 3; ++k)
    if (axis < 0 || k == axis) height = std::max(height, c.box.high[k] - c.box.low[k]);
  fall_speed_ = std::sqrt(2.0 * g * height);
}

// The share of the relaxation time a chosen interval may hold the forces
// for. rho_p / beta estimates the bed's collective time only to its order
// (it leaves out the porosity factors of the bed moving as a whole); a
// fifth of it keeps the hold well inside the explicit limit of two.
constexpr double bed_share = 0.2;

int StabilityWatch::next_interval(const CfdDemCoupling& coupling) {
  const bool explicit_drag = c_.coupling.drag == project::DragCoupling::explicit_force;
  const double drag = coupling.shortest_relaxation(), bed = coupling.shortest_bed_relaxation();
  int steps = interval_;
  if (!given_) {
    const double limit = explicit_drag ? std::min(drag, bed) : bed;
    if (std::isfinite(limit)) steps = std::clamp(static_cast<int>(bed_share * limit / dt_), 1, interval_);
  }
  ++updates_;
  last_ = steps;
  shortest_ = updates_ == 1 ? steps : std::min(shortest_, steps);
  if (std::isfinite(drag)) held_over_drag_ = std::max(held_over_drag_, steps * dt_ / drag);
  if (std::isfinite(bed)) held_over_bed_ = std::max(held_over_bed_, steps * dt_ / bed);
  return steps;
}

nlohmann::json StabilityWatch::summary(const CfdDemCoupling& coupling) const {
  auto finite = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); };
  nlohmann::json series = nlohmann::json::array();
  for (const auto& r : series_) series.push_back({r.t, r.energy, r.fastest, r.bound});
  return {{"drag", c_.coupling.drag == project::DragCoupling::semi_implicit ? "semi_implicit" : "explicit"},
          {"interval_steps", {{"given", given_}, {"longest", interval_}, {"shortest", shortest_}}},
          {"fluid_updates", updates_},
          {"shortest_drag_relaxation_s", finite(coupling.shortest_relaxation())},
          {"shortest_bed_relaxation_s", finite(coupling.shortest_bed_relaxation())},
          {"held_over_drag_relaxation", held_over_drag_},
          {"held_over_bed_relaxation", held_over_bed_},
          {"dem_step_over_rayleigh", dt_ / project::rayleigh_time(c_.grains)},
          {"peak_kinetic_energy_J", peak_energy_.energy},
          {"peak_kinetic_energy_at_s", peak_energy_.t},
          {"fastest_grain_m_s", peak_speed_.fastest},
          {"fastest_grain_at_s", peak_speed_.t},
          {"speed_bound_m_s", speed_bound()},
          {"series_columns", {"t_s", "kinetic_energy_J", "fastest_grain_m_s", "speed_bound_m_s"}},
          {"series", series}};
}

void StabilityWatch::check(double t, const CfdDemCoupling& coupling, bool sample) {
  const auto m = coupling.motion();
  if (water_ < 0.0) {
    double imposed = 0.0;
    if (c_.flow && !c_.flow->inflow_pressure)
      for (const auto& [time, u] : c_.flow->darcy_velocity) imposed = std::max(imposed, std::abs(u));
    water_ = imposed > 0.0 ? imposed / c_.fluid.min_porosity : fastest_water(coupling.grid());
  }
  const double bound = speed_bound();
  const Row row{t, m.energy, m.fastest, bound};
  if (sample) series_.push_back(row);
  if (m.energy >= peak_energy_.energy) peak_energy_ = row;
  if (m.fastest >= peak_speed_.fastest) peak_speed_ = row;
  if (m.fastest <= 3.0 * bound && m.energy <= 0.5 * m.mass * bound * bound) return;
  const double relaxation = coupling.shortest_relaxation(), bed = coupling.shortest_bed_relaxation();
  const double held = last_ * dt_;
  const bool explicit_drag = c_.coupling.drag == project::DragCoupling::explicit_force;
  auto below = [&](double tau) { return std::max(1, static_cast<int>(bed_share * tau / dt_)); };
  std::string cause;
  if (explicit_drag && std::isfinite(relaxation) && held > 0.5 * relaxation)
    cause = fmt::format(
        "the drag is held for {} steps ({:.3g} s), {:.2f} of the shortest drag relaxation time m/K ({:.3g} s): "
        "use \"coupling.drag\": \"semi_implicit\" or a coupling.interval below {}",
        last_, held, held / relaxation, relaxation, below(relaxation));
  else if (std::isfinite(bed) && held > bed_share * bed)
    cause = fmt::format(
        "the pressure gradient is held for {} steps ({:.3g} s), {:.2f} of the bed's relaxation time rho_p/beta "
        "({:.3g} s): a coupling.interval below {}, or none (chosen)",
        last_, held, held / bed, bed, below(bed));
  else
    cause = fmt::format("the DEM step ({:.3g} s) is {:.2f} of the grains' Rayleigh time, the forces held within "
                        "their relaxation times: shorten coupling.dem_timestep",
                        dt_, dt_ / project::rayleigh_time(c_.grains));
  throw UnstableRun(fmt::format(
      "the grains' motion became unstable at t = {:.4g} s: kinetic energy {:.3g} J, the fastest grain at {:.3g} m/s, "
      "where a fall through the box and the water's fastest flow give at most {:.3g} m/s; likely cause: {}",
      t, m.energy, m.fastest, bound, cause));
}

}  // namespace frostwall::cfd_dem
