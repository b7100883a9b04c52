// Calibration from thermometers: what `frostwall calibrate` fits, within
// which bounds, and the readings it fits to. Plain structs read by
// lib/project (load_calibrate.hpp); the fit is lib/calibrate's.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frostwall::project {

// The ground's parameters a calibration may fit.
enum class CalibratedParameter {
  conductivity_frozen,    // factor on the soil's frozen conductivity
  conductivity_unfrozen,  // factor on the soil's unfrozen conductivity
  latent_heat,            // factor on the soil's latent heat
  initial_temperature,    // degC
  darcy_flux,             // the regional flux's magnitude, m/d (its direction kept)
};

// The name in the project file ("conductivity_frozen", ...).
const char* parameter_name(CalibratedParameter p);

struct FittedParameter {
  CalibratedParameter which = CalibratedParameter::conductivity_frozen;
  double low = 0.0, high = 0.0;  // bounds, in the parameter's unit
  double start = 0.0;            // the project's own value (1 for a factor)
};

// One line of the readings file.
struct Reading {
  int line = 0;              // in the file (the header is line 1)
  std::size_t sensor = 0;    // index into Project::monitoring
  double time = 0.0;         // s
  double temperature = 0.0;  // degC
  // The plant's return temperature (sensor "return" of a project with a
  // plant), not a thermometer: `sensor` is then unused.
  bool plant_return = false;
};

struct Calibration {
  std::string file;               // the readings file as written in the project (for messages)
  std::string path;               // resolved against the project file's folder
  std::vector<Reading> readings;  // in the file's order
  std::vector<FittedParameter> parameters;
  // The thermometers' standard uncertainty, K; nullopt: estimated from the
  // misfit at the optimum.
  std::optional<double> noise;
  // The day the forecast's wall is read at, s; nullopt: the run's end.
  std::optional<double> design_time;
  // numerics.step_change of the fit's runs (at most the project's); by
  // default the project's own, so that a forward run is the run `frostwall
  // run` makes, step for step.
  double step_change = 0.0;
};

}  // namespace frostwall::project
