// A plain geometry's rectangle and its sides (geometry.type "rectangle";
// a side is also the form of a shaft's domain.far_field). Internal to
// lib/project; problems go to the Node.
#pragma once

#include <optional>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// "adiabatic", {"temperature": T}, {"temperature": T, "head": h} or
// {"head": h}; head set when one is given.
SideCondition read_side(const Node& n, std::optional<double>& head);
Rectangle read_rectangle(const Node& n);

}  // namespace frostwall::project::detail
