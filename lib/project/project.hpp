// The project file, read once at the edge into plain validated structs.
// Nothing past lib/project sees JSON. Units inside these structs are SI
// (seconds, metres) except temperatures, which stay in degrees Celsius.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "project/as_built.hpp"
#include "project/calibrate.hpp"
#include "project/cfd_dem.hpp"
#include "project/design.hpp"
#include "project/groundwater.hpp"
#include "project/input_error.hpp"
#include "project/mechanics.hpp"
#include "project/numerics.hpp"
#include "project/excavation.hpp"
#include "project/plant.hpp"
#include "project/schedule.hpp"
#include "project/units.hpp"

namespace frostwall::project {

// ---- soil ------------------------------------------------------------------

struct PhaseProperties {
  std::array<double, 2> conductivity{};  // [kx, ky] W/(m K); equal when isotropic
  double heat_capacity = 0.0;            // J/(kg K)
  bool anisotropic() const { return conductivity[0] != conductivity[1]; }
};

// How the pore water freezes below the freezing point (docs/reference/common.md,
// soil.freezing_curve): step (all at Tf), linear (over freezing_range),
// exponential (InterFrost: S_w = S_r + (1 - S_r) exp(-((T - Tf)/W)^2)) or
// power (Anderson and Tice: unfrozen water content w_u = alpha theta^beta,
// theta = Tf - T in K, beta < 0; the liquid share min(1, w_u / w)).
enum class CurveModel { step, linear, exponential, power };
struct FreezingCurve {
  CurveModel model = CurveModel::step;
  double width = 0.0;                // exponential: W, K
  double residual_saturation = 0.0;  // exponential: S_r
  double alpha = 0.0, beta = 0.0;    // power: kg water per kg solid at theta = 1 K, and the exponent
  double water_content = 0.0;        // power: kg water per kg solid when unfrozen
  bool smooth() const { return model == CurveModel::exponential || model == CurveModel::power; }
  // A smooth curve at freezing point Tf: the liquid share at T (1 at and
  // above the onset); where the water begins to freeze (the power law
  // theta* = (w / alpha)^(1/beta) below Tf); where the phase law's table
  // ends (the exponential's share within 1e-6 of S_r, the power law 60 K
  // below its onset, colder than any brine).
  double liquid_fraction(double T, double Tf) const;
  double onset(double Tf) const;
  double bottom(double Tf) const;
};

struct Soil {
  std::string name;
  double density = 0.0;  // kg/m3
  PhaseProperties unfrozen;
  PhaseProperties frozen;
  double latent_heat = 0.0;     // J per kg of soil
  double freezing_point = 0.0;  // degC
  double freezing_range = 0.0;  // K; latent heat released over [Tf - range, Tf]
  // The curve; step and linear follow freezing_range. Exponential and power
  // release the latent heat as the unfrozen water share falls: the share
  // is the liquid fraction, and heat capacity (and, for a soil from its
  // constituents, conductivity) follow it.
  FreezingCurve freezing_curve;
  // The pore space's share of the volume, when the soil is given by its
  // constituents (0: not known).
  double porosity = 0.0;
  // Conductivity between frozen and unfrozen: geometric in the liquid
  // fraction (a soil from its constituents mixed geometrically), else linear.
  bool geometric_conductivity = false;
};

// ---- boundaries of a plain geometry ------------------------------------------

struct Adiabatic {};
struct FixedTemperature {
  TemperatureSchedule temperature;
};
using SideCondition = std::variant<Adiabatic, FixedTemperature>;

// ---- pores of a porous plate (frost damage) ----------------------------------

// A pore: a disc, m, holding water to its degree of saturation S (the
// water's share of the pore's volume, in (0, 1]; the rest is air). Ice
// takes (1 + volume_change) of its water's volume, so a pore loads the
// solid only above S_cr = 1 / (1 + volume_change), 0.917 at 9 %.
struct Pore {
  double x = 0.0, y = 0.0, radius = 0.0;
  double saturation = 1.0;
};

// Pores drawn at random (geometry.pores as an object): `count` discs of
// radius uniform in [radius_min, radius_max], each at least min_gap from
// every other pore and from the plate's sides; the same seed draws the
// same pores. The drawn list is Rectangle::pores (and goes to summary.json).
// Each pore's saturation is uniform in [saturation_min, saturation_max],
// drawn from the same seed after the pores are placed (a range does not
// move them).
struct PoreGenerator {
  int count = 0;
  double radius_min = 0.0, radius_max = 0.0, min_gap = 0.0;  // m
  unsigned long long seed = 0;
  double saturation_min = 1.0, saturation_max = 1.0;
};

// The fluid that fills the pores (project "pore_fluid"): water that
// freezes to ice at freezing_point, releasing latent_heat per kg of water.
struct PoreFluid {
  double water_conductivity = 0.6, ice_conductivity = 2.14;         // W/(m K)
  double water_heat_capacity = 4182.0, ice_heat_capacity = 2060.0;  // J/(kg K)
  double water_density = 1000.0, ice_density = 920.0;               // kg/m3
  double latent_heat = 334e3;                                       // J/kg
  double freezing_point = 0.0;                                      // degC
};

struct Rectangle {
  double width = 0.0;   // along x
  double height = 0.0;  // along y
  SideCondition left, right, top, bottom;
  // Hydraulic heads, m, of the faces left, right, bottom, top (with the
  // groundwater block); a face without one is impermeable.
  std::array<std::optional<double>, 4> heads;
  bool has_heads() const { return heads[0] || heads[1] || heads[2] || heads[3]; }
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
  std::vector<Ring> rings;          // pattern "rings"
  std::vector<PipePosition> pipes;  // pattern "pipes" (measured)
  // Pipes that are off (numbers from 1, in pipe_positions' order): ground
  // like the rest, no boundary.
  std::vector<int> failed_pipes;
};

// How many pipes the layout has (failed ones included): the numbers a
// survey and failed_pipes may use are 1..pipe_count.
int pipe_count(const Layout& layout);

// How a pipe meets the ground: its wall resolved by a circle of fixed
// particles ("disc", also named "resolved"); a line sink at its centre
// joined to the particles near it through the logarithmic profile from its
// wall ("line"); or one fixed particle at its centre ("point").
enum class PipeModel { disc, point, line };
const char* pipe_model_name(PipeModel model);
// The pipe keeps a wall of its diameter in the ground (no particle, sensor
// or profile inside it): the disc and the line sink.
inline bool has_wall(PipeModel model) { return model != PipeModel::point; }

// What holds the pipe wall: a fixed temperature (the wall at the schedule),
// or brine behind a film (Robin: the heat the ground gives up at the wall
// is q = h (T_wall - T_brine) per m2, the schedule being the brine's).
enum class PipeBoundary { fixed, brine };

struct Pipe {
  double diameter = 0.0;            // outer diameter, m
  TemperatureSchedule temperature;  // the wall's (fixed) or the brine's (brine)
  PipeModel model = PipeModel::disc;
  PipeBoundary boundary = PipeBoundary::fixed;
  double heat_transfer_coefficient = 0.0;  // h, W/(m2 K), brine only
  // Brine: h from the annulus' geometry and flow instead of a number.
  std::optional<Annulus> annulus;
  // Held at the heat it draws instead (W per metre of pipe, > 0 cools the
  // ground; in `temperature`'s place, as a schedule): the wall's temperature
  // follows.
  bool heat_extraction = false;
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

// A part of the domain that starts at its own temperature: a rectangle
// [x0, y0, x1, y1], a circle [x, y, r] or a polygon's corners (m, in the
// particles' coordinates).
struct InitialZone {
  enum class Shape { rectangle, circle, polygon } shape = Shape::rectangle;
  std::vector<double> numbers;                 // rectangle, circle
  std::vector<std::array<double, 2>> corners;  // polygon
  double temperature = 0.0;
  bool contains(double x, double y) const;
};

struct Domain {
  double initial_temperature = 0.0;
  // Zones over the initial temperature; a later zone lies over an earlier one.
  std::vector<InitialZone> initial_zones;
  // Far field of a shaft section: fixed temperature, or nullopt = adiabatic.
  std::optional<double> far_field_temperature;
};

enum class TimeUnit { s, h, d };

struct TimeSettings {
  double end = 0.0;               // seconds
  TimeUnit unit = TimeUnit::d;    // the unit the user wrote (for output)
  std::vector<double> snapshots;  // seconds, ascending, each in (0, end]
  double unit_seconds() const;    // 1, 3600 or 86400
  const char* unit_name() const;  // "s", "h" or "d"
};

// One layer of the ground the shaft passes: a cross-section of
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
  std::optional<Mechanics> mechanics;      // plain geometries: PD thermo-mechanics
  std::optional<Groundwater> groundwater;  // shafts: water flowing through the ground (none: still water)
  PoreFluid pore_fluid;                    // what fills Rectangle::pores (default water/ice)
  // Shafts through several layers: one run per layer (empty: one run).
  std::vector<Layer> layers;
  // The shaft as built: a survey of the pipes and the depths to check
  // (one full-ring section run each).
  std::optional<Survey> survey;
  Sections sections;
  // With failed pipes: also run the intact layout and show both.
  bool compare_intact = false;
  // Thermometer readings and the parameters `frostwall calibrate` fits to
  // them (`frostwall run` ignores it).
  std::optional<Calibration> calibration;
  // The freezing plant and its brine circuit (none: the pipe's own
  // temperature or brine schedule holds every depth alike).
  std::optional<Plant> plant;
  // Sinking the shaft inside the frozen wall (none: the ground stays).
  std::optional<Excavation> excavation;
  // "physics": "cfd-dem": grains and pore water; then only name,
  // description, time and output above are read.
  std::optional<CfdDem> cfd_dem;
  // Physically implausible but computable input (latent heat above that of
  // pure water, pipe warmer than the freezing point): printed and reported.
  std::vector<std::string> warnings;
};

// Every problem found in a project file, one line each, in the form
// "json.path: what is wrong". Thrown before any work is done.
class ProjectError : public InputError {
 public:
  using InputError::InputError;
};

// The loader's spacing checks, as one problem each (nullopt: fine): a
// rectangle needs 2 rows across and 5 along, a shaft section a spacing no
// larger than the pipe diameter.
std::optional<std::string> rectangle_spacing_problem(const Rectangle& r, double spacing);
std::optional<std::string> shaft_spacing_problem(const ShaftSection& s, double spacing);
// Both on a built project (a coarser twin of the error estimate): throws
// ProjectError naming numerics.spacing.
void check_spacing(const Project& p);

// Reads and validates a project file. Throws ProjectError (never anything
// else for bad content; an unreadable file is also a ProjectError).
Project load_project(const std::string& path);
// The same from text already in memory (tests, the study command).
Project parse_project(const std::string& json_text);
// As above; `source` (a file name) names the text in a problem with the text
// as a whole, such as "not valid JSON". The one-argument form uses "project".
Project parse_project(const std::string& json_text, const std::string& source);
// As above, with files the project names (survey.file) read relative to
// base_directory (empty: the working directory).
Project parse_project(const std::string& json_text, const std::string& source, const std::string& base_directory);

// Built-in soils: "sand", "clay", "silty_clay". nullopt for other names.
std::optional<Soil> builtin_soil(const std::string& name);
// The names builtin_soil knows, in the order of its table.
std::vector<std::string> builtin_soil_names();

}  // namespace frostwall::project
