// `frostwall check`: a project checked as `frostwall run` checks it before
// any work (the same project::ProjectError), without running or writing,
// and what the run would be: the particles or grains, the memory, the
// spacing and time step used, and an estimate of the run time from the
// rates measured in bench/README.md.
#pragma once

#include <string>
#include <vector>

#include "project/project.hpp"

namespace frostwall::run {

// Lines "what: value" describing the run. Throws project::ProjectError as
// run_project would before its first step. Builds the particle cloud (or
// places the grains) to count them: seconds at most; settles nothing.
std::vector<std::string> check_project(const project::Project& p);

// With a plant, one line: the pipes with flow, the films at the coldest
// supply, the plant's supply or capacity, the sections and exchanges.
std::string describe_plant(const project::Project& p, std::size_t sections);

}  // namespace frostwall::run
