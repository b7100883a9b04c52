// Reader of "excavation": the sinking of the shaft, its air and its lining.
// Internal to lib/project; problems go to the Node.
#pragma once

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// The excavation of a shaft project (nullopt without "excavation"): needs
// shaft.excavation_radius, a lining thinner than it, and one entry of
// `days` per section (its layers, its survey's listed depths, or the one
// section).
std::optional<Excavation> read_excavation(const Node& root, const Project& project);

}  // namespace frostwall::project::detail
