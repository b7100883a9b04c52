// Reader of the "groundwater" block; internal to lib/project.
#pragma once

#include <fmt/format.h>

#include "project/groundwater.hpp"
#include "project/json_reader.hpp"

namespace frostwall::project::detail {

Groundwater read_groundwater(const Node& n, bool plain = false);

}  // namespace frostwall::project::detail
