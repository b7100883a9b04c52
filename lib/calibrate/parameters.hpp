// The ground's parameters a calibration fits, applied to a project: the
// forward model of the fit is the project with these values, run as it is.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "project/project.hpp"

namespace frostwall::calibrate {

using project::CalibratedParameter;
using project::FittedParameter;

// The project with each parameter at its value (factors multiply the
// soil's values; initial_temperature in degC, the far field with it where
// the project has the two equal; darcy_flux in m/d along the project's
// flux direction).
project::Project with_values(const project::Project& base, const std::vector<FittedParameter>& parameters,
                             const std::vector<double>& values);

// The project as the fit runs it at these values: with_values, at the
// calibration's step control (base.calibration->step_change).
project::Project fit_project(const project::Project& base, const std::vector<double>& values);

// The project file's text with the fitted values written in (the soil in
// full, domain.initial_temperature, groundwater.darcy_flux) and without
// "calibrate": a project that `frostwall run` runs as calibrated.
std::string calibrated_project_text(const std::string& text, const project::Project& fitted);

// The unit a parameter is given in ("factor", "degC", "m/d").
const char* parameter_unit(CalibratedParameter p);

}  // namespace frostwall::calibrate
