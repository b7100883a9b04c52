// Reader of the freezing plant: "plant", "brine" and the coaxial fields of
// "pipe". Internal to lib/project; problems go to the Node.
#pragma once

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// The pipe's keys that describe the coaxial freeze pipe (only with "plant").
inline constexpr const char* coaxial_keys[] = {"inner_diameter",       "wall_thickness",          "wall_conductivity",
                                               "inner_wall_thickness", "inner_wall_conductivity", "length"};

// The plant of a shaft project (nullopt without "plant"); reports "brine"
// and the coaxial fields given without a plant, and a layer deeper than
// the pipe.
std::optional<Plant> read_plant(const Node& root, const Project& project);

}  // namespace frostwall::project::detail
