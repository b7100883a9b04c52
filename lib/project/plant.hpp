// The freezing plant and the brine circuit of its coaxial freeze pipes
// (project "plant", "brine" and the pipe's coaxial fields): the brine runs
// down one channel of each freeze pipe and back up the other, warming as it
// draws heat from the ground; the plant holds the supply temperature, or
// runs at its capacity. docs/reference/plant.md.
#pragma once

#include <optional>

#include "project/design.hpp"
#include "project/schedule.hpp"

namespace frostwall::project {

// The channel the brine goes down: the annulus between the freeze pipe and
// the inner pipe (returning up the inner pipe), or the inner pipe.
enum class SupplyChannel { annulus, inner };

// The coaxial freeze pipe beyond its outer diameter (pipe.diameter).
struct CoaxialGeometry {
  double inner_diameter = 0.0;           // m: the inner pipe's outer diameter
  double wall_thickness = 0.0;           // m: the freeze pipe's wall
  double wall_conductivity = 0.0;        // W/(m K)
  double inner_wall_thickness = 0.0;     // m
  double inner_wall_conductivity = 0.0;  // W/(m K)
  double length = 0.0;                   // m: from the top of the pipe to its foot
};

// The brine's properties: each one given is held; one not given follows the
// built-in calcium chloride brine (project/cacl2_brine.hpp) of its mass
// fraction at the circuit's mean temperature.
struct BrineOverrides {
  double mass_fraction = 0.29;
  std::optional<double> density, viscosity, conductivity, heat_capacity;
  BrineProperties at(double T) const;  // degC
  double freezing_point() const;       // degC: where the built-in brine begins to freeze
};

struct Plant {
  CoaxialGeometry pipe;
  double flow_per_pipe = 0.0;  // m3/s through one freeze pipe
  SupplyChannel channel = SupplyChannel::annulus;
  BrineOverrides brine;
  // The supply temperature (degC, a schedule); or, with a capacity, the
  // plant's coldest supply.
  TemperatureSchedule supply;
  std::optional<double> capacity;  // W
  double min_supply_temperature = 0.0;
  std::optional<double> cop;               // heat drawn per unit of electricity
  double exchange_interval = 0.0;          // s between the brine's updates (the shortest)
  double longest_exchange_interval = 0.0;  // s: the longest, once the brine settles
};

}  // namespace frostwall::project
