// Reader of a "physics": "cfd-dem" project. Internal to lib/project
// (load_project.cpp calls it); problems go to the Node.
#pragma once

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// Reads name, description, time, output and the CFD-DEM blocks into
// project (project.cfd_dem set).
void read_cfd_dem(const Node& root, Project& project);

TimeSettings read_time(const Node& n);

}  // namespace frostwall::project::detail
