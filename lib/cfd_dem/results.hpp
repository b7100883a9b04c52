// What a CFD-DEM run measures, sample by sample, and the files it leaves:
// summary.json, series.csv. The bed is measured along the flow (inflow to
// outflow face), or along gravity in still water, from the face the grains
// rest on: its length is twice the grains' mean distance from that face
// (exact for a uniform bed), its porosity 1 - grain volume / (area x length).
#pragma once

#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "project/project.hpp"
#include "cfd_dem/coupling.hpp"

namespace frostwall::cfd_dem {

struct CfdDemSample {
  double time = 0.0;                                    // s
  double inflow_velocity = 0.0;                         // Darcy, m/s
  double grains = 0.0;                                  // in the soil region
  double in_cavity = 0.0;                               // fallen into the cavity (centre inside it)
  double bed_length = 0.0;                              // m
  double porosity = 0.0;                                // of the bed
  double contacts = 0.0;                                // grain-grain contacts
  std::array<std::array<double, 3>, 3> mean_force{};    // per grain, by kind (drag, pressure gradient, buoyancy), N
  double pressure_drop = 0.0;                           // inflow face - outflow face (excess), Pa
  double settling_velocity = 0.0;                       // grains' mean velocity along gravity, m/s
  double inflow = 0.0, outflow = 0.0, imbalance = 0.0;  // mixture flow, m3/s; largest cell |net|
  int picard_iterations = 0;
};

class CfdDemResults {
 public:
  explicit CfdDemResults(const project::Project& p);
  CfdDemSample sample(double t, double inflow_velocity, const GrainTotals& totals, const pore_water::FluidGrid& grid,
                      const pore_water::SolveReport& report) const;
  void add(const CfdDemSample& s, bool snapshot);
  const std::vector<CfdDemSample>& series() const { return series_; }
  // Run facts (time step, ranks, timings, packing) go in as given.
  nlohmann::json summary(const nlohmann::json& facts) const;
  std::string csv() const;

 private:
  nlohmann::json fluidisation() const;
  const project::Project& p_;
  const project::CfdDem& c_;
  int axis_ = 2;          // bed axis
  bool from_low_ = true;  // the grains rest on the axis's low face
  double area_ = 0.0;     // cross-section normal to the axis, m2
  std::vector<CfdDemSample> series_;
  std::vector<std::size_t> snapshots_;  // indices into series_
};

}  // namespace frostwall::cfd_dem
