// The numerical error bar of every headline number, measured by the run
// itself (numerics.error_estimate): after the run, the same project runs
// three more times at 1.35, 1.5 and 1.65 times the spacing it used (a
// graded cloud is scaled as a whole; the time steps follow the spacing),
// quietly, without VTK or report, in a scratch directory inside the output
// directory that is removed afterwards. Each headline number then gets an
// error from how it moved (run/error_law.hpp):
//
// - summary.json: "<key>_error" beside each number (closure_time_days,
//   front_contact_days; in every wall entry min_thickness, OA/OB
//   thickness, mean_temperature_OB, the isotherm's thickness and
//   temperature, utilisation and the up- and downstream thickness; design
//   reached_day and met_day; every gap's closure_day under seepage);
//   "front_error", "monitoring_error" and "monitoring_solid_error" beside
//   the series of a plain geometry ([time, error, ...] rows); and an
//   "error_estimate" block saying how it was made (or why it could not be).
// - wall.csv and monitoring.csv: a "<column>_error" column for every
//   column but the first (the time).
//
// Only the discretisation is estimated: the model's physics and the soil's
// data are the user's. CFD-DEM runs have none (another packing is not a
// coarser grid).
#pragma once

#include <array>
#include <functional>
#include <nlohmann/json.hpp>

#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"

namespace frostwall::run {

// The coarse twins' spacings, as multiples of the run's.
inline constexpr std::array<double, 3> coarse_ratios{1.35, 1.5, 1.65};

// Runs one project (the engine, without the estimate); returns its summary.
using EngineRun = std::function<summary::Summary(const project::Project&, const project::RunOptions&)>;

// After `engine` has run p into p.output.directory with the summary `run`:
// runs the twins with `engine`, then adds the errors to `run` and rewrites
// summary.json, wall.csv and monitoring.csv with them. A twin that cannot
// run (a spacing too coarse for the geometry) leaves the numbers without
// errors and says why in the summary.
void add_error_estimate(const project::Project& p, const project::RunOptions& options, const EngineRun& engine,
                        summary::Summary& run);

// The error entries of a run's summary from its twins' summaries (the
// twins' run.spacing gives the ratio); adds them to `summary` in place.
void add_summary_errors(nlohmann::ordered_json& summary, const std::vector<nlohmann::json>& twins);

}  // namespace frostwall::run
