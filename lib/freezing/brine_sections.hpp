// Cross-sections of one shaft at several depths coupled through the brine
// of their coaxial freeze pipes. Each section is a full heat run (its pipes
// held by brine behind a film, h = 1 / (pi d R_ground): the annulus' film
// and the freeze pipe's wall, design/coaxial_pipe.hpp), marched side by side
// with the others to the exchange stops. At each stop:
//  - each section's pipes drew, over the interval, the heat that left its
//    ground through the pipe walls, per metre of one pipe (a pipe on a
//    mirror line counts by its wall's share in the section);
//  - along the pipe the draw is interpolated linearly between the sections'
//    depths (held beyond the first and the last);
//  - the brine's temperatures follow (design::brine_with_draw) with the
//    supply of the stop, and each section's brine for the next interval is
//    the annulus' temperature at its depth.
// Between stops the sections march side by side (the cores shared among
// them). Stops come every `interval` while the plant is held at its
// capacity, and lengthen while the brine settles (CircuitSettings).
// The brine is steady (its own heat capacity left out), so the plant's load
// is the pipes' draw: n m c (T_return - T_supply) equals the sections'
// drawn heat integrated along the pipe with the same weights, to round-off.
//
// The supply follows its schedule, or the plant runs at a capacity P: the
// supply is then the one whose brine draws P over the coming interval, as
// far as the last interval tells (each section's film h pi d (T_w - T_b)
// with its wall's mean temperature over the last interval, T_b the supply
// plus the brine's warming to that depth at the last draws), never colder
// than the plant's coldest supply. Warm ground at start-up takes P at a
// supply well above the coldest; as it cools the supply falls to it and the
// load below P.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "design/brine_circuit.hpp"
#include "freezing/heat_run.hpp"
#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"

namespace frostwall::freezing {

struct CircuitSection {
  project::Project project;           // a shaft section (its output directory its own)
  double depth = 0.0;                 // m below the pipe's top
  std::string project_text;           // written as the section's project.json (empty: the options')
  RunExtension* extension = nullptr;  // what the section's run also does (heat_run.hpp)
};

struct CircuitSettings {
  design::CoaxialPipe pipe;
  design::Brine brine;
  double flow = 0.0;  // m3/s per pipe
  design::SupplyChannel channel = design::SupplyChannel::annulus;
  project::TemperatureSchedule supply;  // without a capacity
  std::optional<double> capacity;       // W: the plant at its capacity
  double min_supply = 0.0;              // degC, with a capacity
  int pipes = 1;                        // pipes on the plant, in parallel
  double interval = 0.0;                // s between exchanges (the shortest)
  // The longest, s: exchanges lengthen, doubling, while the plant is not
  // held at its capacity and no section's brine moves by more than
  // `settled` K over one (the brine then hardly changes; a held brine's
  // run does not depend on how often it is refreshed). 0: never longer.
  double longest_interval = 0.0;
  double settled = 0.02;
  int cells = 200;  // along the pipe
  // The brine's properties at a temperature (degC); set, they are taken at
  // each exchange at the circuit's mean temperature over the last interval
  // (the supply's and the return's mean; at the start, the supply), and the
  // films and the sections' walls follow. Unset: `brine` throughout.
  std::function<design::Brine(double)> brine_at;
  std::vector<double> profile_times;  // s: the brine along the pipe kept at the first stop from each
};

struct PlantRow {
  double time = 0.0;                              // s: the end of the interval
  double load = 0.0;                              // W, all pipes: the heat drawn over the interval, per second
  double supply = 0.0, return_temperature = 0.0;  // the return as the interval's draws warm the supply
  // Each over the interval that ends at `time`:
  std::vector<double> brine;  // the annulus' temperature at each section's depth
  std::vector<double> draw;   // W per metre of one pipe each section drew
  double film = 0.0;          // h on the freeze pipe's outer wall, W/(m2 K)
};

// The brine along the pipe at a stop: the channels' temperatures at the
// cells' faces and the heat drawn per metre in each cell.
struct PlantProfile {
  double time = 0.0;
  design::BrineProfile brine;
};

struct CircuitRun {
  std::vector<summary::Summary> sections;
  std::vector<PlantRow> series;
  double plant_heat = 0.0;      // J: the loads over their intervals
  double ground_heat = 0.0;     // J: the sections' pipe walls' heat, all pipes, with the depth weights
  std::vector<double> weights;  // m of pipe each section stands for
  std::vector<PlantProfile> profiles;
  design::CoaxialResistances resistances;  // as last taken
  design::Brine brine;                     // as last taken
};

CircuitRun run_brine_circuit(const std::vector<CircuitSection>& sections, const CircuitSettings& settings,
                             const project::RunOptions& options);

}  // namespace frostwall::freezing
