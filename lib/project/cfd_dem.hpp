// A CFD-DEM project ("physics": "cfd-dem"): soil grains (LAMMPS, lib/dem)
// in pore water on a coarse grid (lib/pore_water). Plain validated
// structs, SI units; the engine never sees JSON. The z axis is vertical in
// every shipped project; gravity is a vector, so any axis may be.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace frostwall::project {

using Point3 = std::array<double, 3>;

// The box's faces in the order x_min, x_max, y_min, y_max, z_min, z_max
// (the fluid grid's face index): axis = face / 2, upper side = face % 2.
enum class BoxFace { x_min, x_max, y_min, y_max, z_min, z_max };
const char* face_name(BoxFace f);

struct GrainSettings {
  double diameter_min = 0.0, diameter_max = 0.0;  // m; uniform in between, equal for one size
  double density = 2650.0;                        // kg/m3
  double youngs_modulus = 5e7;                    // Pa (Hertz contact)
  double poisson_ratio = 0.3;
  double restitution = 0.5;  // normal coefficient of restitution (Tsuji damping)
  double friction = 0.5;     // sliding, Coulomb
  // Sliding friction while settling (default: friction): a low value packs
  // the grains denser, the usual way DEM prepares a dense sand.
  std::optional<double> settle_friction;
  double rolling_friction = 0.0;  // rolling resistance coefficient (0: none)
  // Packing: a grain count, or the porosity of the fill region (minus the
  // cavity) that sets the count.
  std::optional<long> count;
  std::optional<double> porosity;
  // Where grains are placed (default: the box). It may reach above the
  // box against gravity: a settling column, trimmed to the box after
  // settling (the grains above the box's top are taken away).
  Point3 fill_low{}, fill_high{};
  unsigned long long seed = 1;
  double settle_time = 0.0;  // s under gravity, still water, before the flow opens
  bool held = false;         // a fixed bed: grains never move
  double mean_diameter() const { return 0.5 * (diameter_min + diameter_max); }
};

struct CfdDemBox {
  Point3 low{}, high{};                               // m
  std::array<bool, 3> periodic{false, false, false};  // for the grains; the fluid sees walls
};

// An unlined void in the ground. By default it keeps what falls into it
// (grains pile up in it until it is full); with drain a leak carries every
// grain whose centre enters it away (deleted).
struct Cavity {
  Point3 centre{};
  double radius = 0.0;
  bool drain = false;
};

// A heap: the grains settle in a container over the fill region on the
// box's floor; as the run starts its sides are lifted at lift_speed and the
// block slumps into a heap round this vertical axis, whose flank the run
// measures (the angle of repose).
struct Heap {
  std::array<double, 2> axis{};  // m, across gravity (x, y)
  double lift_speed = 0.005;     // m/s: the container's sides lifted off the settled block
};

struct FluidSettings {
  double density = 1000.0;     // kg/m3
  double viscosity = 1e-3;     // dynamic, Pa s
  std::array<int, 3> cells{};  // grid cells per axis (from cell_size when given so)
  bool cells_given = false;    // "cells" was written (else "cell_size"): what messages name
  double min_porosity = 0.3;   // voidage clamp of the coarse cells
};

// The flow: the Darcy (superficial) velocity into the inflow face, a
// schedule [[s, m/s], ...] linear in between; or a fixed excess pressure
// there. The outflow face is at a fixed excess pressure. Other faces are
// impermeable walls.
struct FlowSettings {
  BoxFace inflow = BoxFace::z_min;
  std::vector<std::pair<double, double>> darcy_velocity;  // (s, m/s); empty with inflow_pressure
  std::optional<double> inflow_pressure;                  // Pa
  BoxFace outflow = BoxFace::z_max;
  double outflow_pressure = 0.0;  // Pa
  // Grains may leave through the outflow face (washed out: no wall there);
  // else a screen holds them.
  bool open_to_grains = false;
  double velocity_at(double t) const;
};

// The fluid forces on a grain, by name (lib/pore_water/grain_forces.hpp).
inline const std::vector<std::string> default_fluid_forces{"difelice_drag", "pressure_gradient", "buoyancy"};

// How the drag between updates is applied: `semi_implicit` holds each
// grain's drag coefficient K and its fluid velocity u and applies
// K (u - v) with the grain's velocity v of every DEM step (CFDEMcoupling's
// implicit momentum exchange); `explicit` holds the force itself.
enum class DragCoupling { semi_implicit, explicit_force };

struct CouplingSettings {
  std::optional<int> interval;         // DEM steps per fluid update (nullopt: chosen)
  std::optional<double> dem_timestep;  // s (nullopt: 0.2 of the Rayleigh time)
  DragCoupling drag = DragCoupling::semi_implicit;
};

// LAMMPS' neighbour lists. The list is always rebuilt once a grain has
// moved half the skin (check yes), so with every = 1 no contact is ever
// missed and these settings change the speed, not the answer.
struct NeighbourSettings {
  std::optional<double> skin;      // m (nullopt: a quarter of the largest grain)
  int every = 1;                   // steps between the moved-half-the-skin checks
  std::optional<double> bin_size;  // m (nullopt: LAMMPS' half the cutoff)
};

// The Rayleigh time of the smallest grain, s: pi R sqrt(rho / G) /
// (0.1631 nu + 0.8766). The DEM step is a fraction of it.
double rayleigh_time(const GrainSettings& g);
// The largest DEM step accepted, as a fraction of the Rayleigh time: at
// 0.5 LAMMPS loses grains (bench/README.md); the shipped cases use 0.3.
inline constexpr double max_rayleigh_fraction = 0.4;
// The smallest neighbour bin accepted, as a fraction of the smallest grain's diameter.
inline constexpr double min_bin_fraction = 0.1;

struct CfdDem;
// The axis gravity runs along most (0, 1, 2), or -1 without gravity.
int gravity_axis(const CfdDem& c);

struct CfdDem {
  GrainSettings grains;
  CfdDemBox box;
  std::optional<Cavity> cavity;
  std::optional<Heap> heap;
  FluidSettings fluid;
  std::optional<FlowSettings> flow;  // none: still water
  Point3 gravity{0.0, 0.0, -9.81};   // m/s2
  std::vector<std::string> forces = default_fluid_forces;
  CouplingSettings coupling;
  NeighbourSettings neighbour;
  // The point whose fluid cell is watched (pressure, forces on its grains):
  // the paper's "point A, 0.04 m below the surface above the cavity".
  // Default with a cavity: above its centre, 0.04 m below the box's top.
  std::optional<Point3> point_a;
  std::optional<double> max_grains;  // refuse above (nullopt: from the machine's memory)
};

}  // namespace frostwall::project
