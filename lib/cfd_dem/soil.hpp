// What the CFD-DEM paper measures of the ground over a leak,
// found from every rank's grains at an output time (collective calls):
// the porosity of the zone above the cavity, the fluid at point A's cell
// and the forces on its grains, the surface's settlement along the line
// through the cavity, and the collapse zone (grains displaced more than
// two diameters) with the angle of its boundary.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "dem/lammps_session.hpp"
#include "project/cfd_dem.hpp"
#include "cfd_dem/coupling.hpp"
#include "cfd_dem/surface_map.hpp"

namespace frostwall::cfd_dem {

struct SoilMeasures {
  double zone_porosity = NAN;                           // the cylinder over the cavity's crown, to the box's top
  double pressure_drop_a = NAN;                         // inflow face's pressure less point A's cell's, Pa
  double grains_a = 0.0;                                // grains in point A's cell
  std::array<std::array<double, 3>, 3> mean_force_a{};  // per grain there, by kind (drag, pressure gradient, buoyancy)
  std::vector<double> surface;                          // the surface's height per bin along x, m
  double settlement_max = 0.0;                          // the deepest settlement, m
  double settlement_width = 0.0;                        // width where it exceeds one grain diameter, m
  double displaced = 0.0;                               // grains moved more than 2 diameters from where the run started
  double moved = 0.0;                                   // grains moved more than 1 diameter
  std::optional<double> cone_angle;                     // the collapse zone's boundary from the horizontal, degrees
  std::optional<double> slip_angle;  // likewise for the grains moved more than one diameter: the slip surface
  std::optional<Crater> crater;      // with a cavity: the surface's trough from the height maps
  std::optional<Heap> heap;          // with a heap: its flanks
};

class SoilWatch {
 public:
  // Records where every grain starts and the surface as the run starts.
  SoilWatch(const project::CfdDem& c, const dem::LammpsSession& lammps);
  SoilMeasures measure(const CfdDemCoupling& coupling) const;
  const std::vector<double>& bins() const { return bin_centres_; }  // x of the surface bins, m
  const std::vector<double>& initial_surface() const { return initial_surface_; }
  // Where grain `id` was as the run started (NaN for an id not known then).
  std::array<double, 3> start(int id) const {
    return static_cast<std::size_t>(id) < start_.size() ? start_[id] : std::array<double, 3>{NAN, NAN, NAN};
  }

 private:
  std::vector<double> surface() const;  // collective
  const project::CfdDem& c_;
  const dem::LammpsSession& lammps_;
  double bin_width_ = 0.0;
  std::vector<double> bin_centres_, initial_surface_;
  HeightMap initial_map_;
  std::vector<std::array<double, 3>> start_;  // by grain id
};

// The ground's record over a run: one row per output time, the surface
// profile at the snapshots; summary.json's "soil" and soil.csv.
struct SoilRow {
  double time = 0.0;
  double grains = 0.0;        // in the soil
  double lost_cavity = 0.0;   // entered the cavity since the start (kept there, or deleted by a drain)
  double lost_outflow = 0.0;  // washed out through the outflow face since the start
  double contacts = 0.0;
  SoilMeasures measures;
  double in_cavity = 0.0;  // grains whose centre lies in the cavity now
  double in_model = 0.0;   // grains in the model (soil and a kept cavity's)
};

// The packing's regime: its porosity (box less cavity), Terzaghi's
// critical gradient (G_s - 1)(1 - n), Ergun's minimum fluidisation
// velocity for an upward flow, and for the flow's largest Darcy velocity
// the hydraulic gradient Ergun gives and whether it is above that.
nlohmann::json packing_regime(const project::CfdDem& c, double grain_volume);

class SoilRecord {
 public:
  explicit SoilRecord(const project::CfdDem& c) : c_(c) {}
  void add(SoilRow row, bool snapshot);
  // The packing's regime numbers (critical gradient, Ergun's minimum
  // fluidisation velocity for an upward flow) come in as given.
  nlohmann::json summary(const nlohmann::json& regime, const std::vector<double>& bins,
                         const std::vector<double>& initial_surface) const;
  std::string csv() const;

 private:
  const project::CfdDem& c_;
  std::vector<SoilRow> rows_;
  std::vector<std::size_t> snapshots_;
};

}  // namespace frostwall::cfd_dem
