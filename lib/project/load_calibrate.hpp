// Reader of "calibrate": the readings file and the parameters to fit.
// Internal to lib/project; problems go to the Node.
#pragma once

#include <optional>
#include <string>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// "calibrate": {"readings", "parameters", "noise", "design_day", "step_change"}, read after
// the rest of the project (sensors, soil, time, groundwater). The readings
// file is relative to base_directory; each of its problems names the file
// and the line.
std::optional<Calibration> read_calibration(const Node& n, const Project& project, const std::string& base_directory);

}  // namespace frostwall::project::detail
