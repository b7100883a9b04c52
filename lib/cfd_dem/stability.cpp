#include "cfd_dem/stability.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <mpi.h>

namespace frostwall::cfd_dem {

double fastest_water(const pore_water::FluidGrid& grid) {
  const auto U = grid.superficial_velocity();
  const auto& eps = grid.porosity();
  double fastest = 0.0;
  for (std::size_t i = 0; i < U.size(); ++i) fastest = std::max(fastest, U[i].norm() / std::max(eps[i], 1e-3));
  return fastest;
}

StabilityWatch::StabilityWatch(const project::CfdDem& c, double dt, int interval)
    : c_(c), dt_(dt), interval_(interval) {
  // The box's height along gravity (its largest extent without gravity's direction).
  const double g = std::hypot(c.gravity[0], c.gravity[1], c.gravity[2]);
  const int axis = project::gravity_axis(c);
  double height = 0.0;
  for (int k = 0; k < 3; ++k)
    if (axis < 0 || k == axis) height = std::max(height, c.box.high[k] - c.box.low[k]);
  fall_speed_ = std::sqrt(2.0 * g * height);
}

double StabilityWatch::speed_bound(double u_water) const { return fall_speed_ + u_water; }

namespace {

double shortest_relaxation(const CfdDemCoupling& coupling) {
  double relaxation = coupling.shortest_relaxation();
  MPI_Allreduce(MPI_IN_PLACE, &relaxation, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return relaxation;
}

}  // namespace

nlohmann::json StabilityWatch::summary(const CfdDemCoupling& coupling) const {
  const double relaxation = shortest_relaxation(coupling);
  nlohmann::json series = nlohmann::json::array();
  for (const auto& r : series_) series.push_back({r.t, r.energy, r.fastest, r.bound});
  const double held = interval_ * dt_;
  return {{"drag", c_.coupling.drag == project::DragCoupling::semi_implicit ? "semi_implicit" : "explicit"},
          {"held_s", held},
          {"shortest_drag_relaxation_s", std::isfinite(relaxation) ? nlohmann::json(relaxation) : nlohmann::json()},
          {"held_over_relaxation", std::isfinite(relaxation) ? nlohmann::json(held / relaxation) : nlohmann::json()},
          {"dem_step_over_rayleigh", dt_ / project::rayleigh_time(c_.grains)},
          {"peak_kinetic_energy_J", peak_energy_.energy},
          {"peak_kinetic_energy_at_s", peak_energy_.t},
          {"fastest_grain_m_s", peak_speed_.fastest},
          {"fastest_grain_at_s", peak_speed_.t},
          {"speed_bound_m_s", peak_speed_.bound},
          {"series_columns", {"t_s", "kinetic_energy_J", "fastest_grain_m_s", "speed_bound_m_s"}},
          {"series", series}};
}

void StabilityWatch::check(double t, const CfdDemCoupling& coupling, bool sample) {
  const auto m = coupling.motion();
  const double bound = speed_bound(fastest_water(coupling.grid()));
  const Row row{t, m.energy, m.fastest, bound};
  if (sample) series_.push_back(row);
  if (m.energy >= peak_energy_.energy) peak_energy_ = row;
  if (m.fastest >= peak_speed_.fastest) peak_speed_ = row;
  if (m.fastest <= 3.0 * bound && m.energy <= 0.5 * m.mass * bound * bound) return;
  const double relaxation = shortest_relaxation(coupling);
  const double held = interval_ * dt_;
  const double rayleigh = project::rayleigh_time(c_.grains);
  const bool explicit_drag = c_.coupling.drag == project::DragCoupling::explicit_force;
  std::string cause;
  if (explicit_drag && std::isfinite(relaxation) && held > 0.5 * relaxation)
    cause = fmt::format(
        "the drag is held for {} steps ({:.3g} s), {:.2f} of the shortest drag relaxation time m/K ({:.3g} s): "
        "use \"coupling.drag\": \"semi_implicit\" or a coupling.interval below {}",
        interval_, held, held / relaxation, relaxation, std::max(1, static_cast<int>(0.25 * relaxation / dt_)));
  else
    cause = fmt::format("the DEM step ({:.3g} s) is {:.2f} of the grains' Rayleigh time and the drag is {}: "
                        "shorten coupling.dem_timestep",
                        dt_, dt_ / rayleigh, explicit_drag ? "held within its relaxation time" : "semi-implicit");
  throw UnstableRun(fmt::format(
      "the grains' motion became unstable at t = {:.4g} s: kinetic energy {:.3g} J, the fastest grain at {:.3g} m/s, "
      "where a fall through the box and the water's fastest flow give at most {:.3g} m/s; likely cause: {}",
      t, m.energy, m.fastest, bound, cause));
}

}  // namespace frostwall::cfd_dem
