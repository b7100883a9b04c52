// The project file, read once at the edge into plain validated structs.
// Nothing past lib/project sees JSON. Units inside these structs are SI
// (seconds, metres) except temperatures, which stay in degrees Celsius.
#pragma once

#include "design/annulus_film.hpp"
#include "design/wall_strength.hpp"

#include <array>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "project/cfd_dem.hpp"
#include "project/groundwater.hpp"
#include "project/mechanics.hpp"

namespace frostwall::project {

// ---- soil ------------------------------------------------------------------

struct PhaseProperties {
  std::array<double, 2> conductivity{};  // [kx, ky] W/(m K); equal when isotropic
  double heat_capacity = 0.0;            // J/(kg K)
  bool anisotropic() const { return conductivity[0] != conductivity[1]; }
};

struct Soil {
  std::string name;
  double density = 0.0;  // kg/m3
  PhaseProperties unfrozen;
  PhaseProperties frozen;
  double latent_heat = 0.0;     // J per kg of soil
  double freezing_point = 0.0;  // degC
  double freezing_range = 0.0;  // K; latent heat released over [Tf - range, Tf]
};

// ---- temperatures that may change in time ----------------------------------

// A wall temperature: constant, or [time, degC] points linear in between and
// held constant outside the first and last point.
struct TemperatureSchedule {
  std::vector<std::pair<double, double>> points;  // (seconds, degC), sorted
  double at(double t_seconds) const;
  bool constant() const { return points.size() == 1; }
  static TemperatureSchedule fixed(double degC) { return {{{0.0, degC}}}; }
};

// ---- boundaries of a plain geometry ------------------------------------------

struct Adiabatic {};
struct FixedTemperature {
  TemperatureSchedule temperature;
};
using SideCondition = std::variant<Adiabatic, FixedTemperature>;

// ---- pores of a porous plate (frost damage) ----------------------------------

// A water-filled pore: a disc, m.
struct Pore {
  double x = 0.0, y = 0.0, radius = 0.0;
};

// Pores drawn at random (geometry.pores as an object): `count` discs of
// radius uniform in [radius_min, radius_max], each at least min_gap from
// every other pore and from the plate's sides; the same seed draws the
// same pores. The drawn list is Rectangle::pores (and goes to summary.json).
struct PoreGenerator {
  int count = 0;
  double radius_min = 0.0, radius_max = 0.0, min_gap = 0.0;  // m
  unsigned long long seed = 0;
};

// The fluid that fills the pores (project "pore_fluid"): water that
// freezes to ice at freezing_point, releasing latent_heat per kg of water.
struct PoreFluid {
  double water_conductivity = 0.6, ice_conductivity = 2.14;      // W/(m K)
  double water_heat_capacity = 4182.0, ice_heat_capacity = 2060.0;  // J/(kg K)
  double water_density = 1000.0, ice_density = 920.0;            // kg/m3
  double latent_heat = 334e3;                                    // J/kg
  double freezing_point = 0.0;                                   // degC
};

struct Rectangle {
  double width = 0.0;   // along x
  double height = 0.0;  // along y
  SideCondition left, right, top, bottom;
  std::vector<Pore> pores;                      // explicit or drawn; none: a plain plate
  std::optional<PoreGenerator> pore_generator;  // how they were drawn, when they were
};

// ---- shaft layouts -----------------------------------------------------------

enum class Pattern { single, three_hole, four_hole, rings, pipes };

struct Ring {
  double radius = 0.0;
  int count = 0;
  double offset_deg = 0.0;  // angle of the ring's first pipe
};

struct PipePosition {
  double x = 0.0, y = 0.0;
};

struct Layout {
  Pattern pattern = Pattern::single;
  // single | three-hole | four-hole: the outer ring (its offset is
  // start_angle_deg) and, for the double rings, the inner radius.
  Ring outer_ring;
  std::optional<double> inner_ring_radius;
  std::vector<Ring> rings;           // pattern "rings"
  std::vector<PipePosition> pipes;   // pattern "pipes" (measured)
};

enum class PipeModel { disc, point };

// What holds the pipe wall: a fixed temperature (the wall at the schedule),
// or brine behind a film (Robin: the heat the ground gives up at the wall
// is q = h (T_wall - T_brine) per m2, the schedule being the brine's).
enum class PipeBoundary { fixed, brine };

struct Pipe {
  double diameter = 0.0;  // outer diameter, m
  TemperatureSchedule temperature;  // the wall's (fixed) or the brine's (brine)
  PipeModel model = PipeModel::disc;
  PipeBoundary boundary = PipeBoundary::fixed;
  double heat_transfer_coefficient = 0.0;  // h, W/(m2 K), brine only
  // Brine: h from the annulus' geometry and flow instead of a number.
  std::optional<design::Annulus> annulus;
};

struct Shaft {
  std::optional<double> excavation_radius;
};

struct ShaftSection {
  Layout layout;
  Shaft shaft;
  Pipe pipe;
  double outer_radius = 0.0;  // domain.outer_radius
};

// ---- what every project has ----------------------------------------------------

struct Domain {
  double initial_temperature = 0.0;
  // Far field of a shaft section: fixed temperature, or nullopt = adiabatic.
  std::optional<double> far_field_temperature;
};

enum class TimeUnit { s, h, d };

struct TimeSettings {
  double end = 0.0;                 // seconds
  TimeUnit unit = TimeUnit::d;      // the unit the user wrote (for output)
  std::vector<double> snapshots;    // seconds, ascending, each in (0, end]
  double unit_seconds() const;      // 1, 3600 or 86400
};

enum class KernelKind { wendland_c2, cubic_spline };
enum class IntegratorKind { explicit_euler, implicit, rkl2 };
enum class ConductivityMean { harmonic, arithmetic };
enum class LaplacianForm { renormalised, plain };
enum class Placement { lattice, graded };
// The particle method of heat conduction: SPH pair weights or PD thermal bonds.
enum class Method { sph, pd };

// numerics.placement "graded": the spacing grows from numerics.spacing
// (finest, at the pipe walls) through a wall band to a coarse far field.
struct Grading {
  double coarsening = 8.0;       // coarsest spacing / finest
  double growth = 1.2;           // largest ratio of the spacings of neighbouring particles
  double band_coarsening = 1.0;  // spacing in the wall band / finest
  // Half-width of the wall band, m: beyond the innermost and outermost pipe
  // rings (shaft sections) or from the cooled face (rectangles). nullopt =
  // frostwall chooses (2 m round the rings; a third of a rectangle).
  std::optional<double> band_width;
};

struct Numerics {
  std::optional<double> spacing;  // m; nullopt = frostwall chooses
  KernelKind kernel = KernelKind::wendland_c2;
  double smoothing_ratio = 1.3;   // h / spacing
  IntegratorKind integrator = IntegratorKind::rkl2;
  double beta = 0.1;              // explicit step: dt = beta h^2 / alpha_max
  // RKL2 and implicit steps: the largest enthalpy change of a particle per
  // step, as a fraction of the latent heat (the step adapts to hold it).
  // Default 1 for RKL2, 0.25 for implicit (load_project).
  double step_change = 0.25;
  ConductivityMean conductivity_mean = ConductivityMean::harmonic;
  LaplacianForm laplacian = LaplacianForm::renormalised;
  Method method = Method::sph;
  // PD horizon delta in spacings; 3.015 so that no neighbour sits exactly
  // on it (the Madenci & Oterkus book code's choice).
  double horizon = 3.015;
  // Shaft sections: simulate the smallest mirror-symmetric wedge ("auto"),
  // or the whole ring ("off"; a check of the wedge, or for asymmetric ground).
  bool use_symmetry = true;
  Placement placement = Placement::lattice;  // default graded for shaft sections (load_project)
  Grading grading;
  // Refuse a project estimated to need more free particles than this
  // (nullopt: from the machine's memory, run/capacity.hpp).
  std::optional<double> max_particles;
};

// The wall check (issue 18): a target thickness typed in, or the thickness
// the ground pressure needs from the frozen soil's strength at the wall's
// mean temperature (design/wall_strength.hpp).
struct Design {
  std::optional<double> required_thickness;    // m
  std::optional<double> max_mean_temperature;  // degC
  std::optional<design::StrengthLaw> strength;  // uniaxial compressive, MPa
  double allowable_factor = 0.5;
  std::optional<double> depth;                 // m
  std::optional<double> pressure;              // lateral, MPa, at the depth
  design::Formula formula = design::Formula::domke;  // the governing one
  std::optional<double> friction_angle;        // degrees: Mohr-Coulomb's plastic limit
  // The design isotherm (degC): the wall is also measured on the part of
  // each ray colder than this, and the check then uses that wall.
  std::optional<double> isotherm;
  bool checks_strength() const { return strength && pressure; }
};

// One layer of the ground the shaft passes (issue 18): a cross-section of
// its own at its depth, with its soil, pressure and strength. The JSON of
// its soil and design entries is kept as given, so that the layer's run
// records the project file it ran (project.json) like any other run.
struct Layer {
  std::string name;
  double depth = 0.0;  // m
  Soil soil;
  double pressure = 0.0;  // MPa, lateral, at the depth
  std::string patch;      // the layer as a JSON merge patch of the project file
};

struct Sensor {
  std::string name;
  double x = 0.0, y = 0.0;  // m; r/theta inputs are converted on reading
};

// A segment along which a plain geometry's frozen front is reported at
// every snapshot: the distance from `from` to the first 0.5 crossing of
// the liquid fraction (the corner freezing case: along the diagonal).
struct FrontLine {
  double from_x = 0.0, from_y = 0.0, to_x = 0.0, to_y = 0.0;  // m
};

struct Output {
  std::string directory;  // relative to the working directory
  bool vtk = true;
  bool full_ring = true;
  bool report = true;
  std::vector<FrontLine> front_along;  // plain geometries
};

struct Project {
  std::string name;
  std::string description;
  std::variant<ShaftSection, Rectangle> geometry;
  Soil soil;
  Domain domain;
  TimeSettings time;
  Numerics numerics;
  Design design;
  std::vector<Sensor> monitoring;
  Output output;
  std::optional<Mechanics> mechanics;  // plain geometries: PD thermo-mechanics
  std::optional<Groundwater> groundwater;  // shafts: water flowing through the ground (none: still water)
  PoreFluid pore_fluid;                // what fills Rectangle::pores (default water/ice)
  // Shafts through several layers: one run per layer (empty: one run).
  std::vector<Layer> layers;
  // "physics": "cfd-dem": grains and pore water; then only name,
  // description, time and output above are read.
  std::optional<CfdDem> cfd_dem;
  // Physically implausible but computable input (latent heat above that of
  // pure water, pipe warmer than the freezing point): printed and reported.
  std::vector<std::string> warnings;
};

// Every problem found in a project file, one line each, in the form
// "json.path: what is wrong". Thrown before any work is done.
class ProjectError : public std::runtime_error {
 public:
  explicit ProjectError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

// Reads and validates a project file. Throws ProjectError (never anything
// else for bad content; an unreadable file is also a ProjectError).
Project load_project(const std::string& path);
// The same from text already in memory (tests, the study command).
Project parse_project(const std::string& json_text);
// As above; `source` (a file name) names the text in a problem with the text
// as a whole, such as "not valid JSON". The one-argument form uses "project".
Project parse_project(const std::string& json_text, const std::string& source);

// Built-in soils: "sand", "clay", "silty_clay". nullopt for other names.
std::optional<Soil> builtin_soil(const std::string& name);
// The names builtin_soil knows, in the order of its table.
std::vector<std::string> builtin_soil_names();

}  // namespace frostwall::project
