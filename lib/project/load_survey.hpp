// Readers of the shaft as built: "survey", "sections" and "failed_pipes".
// Internal to lib/project; problems go to the Node.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "project/json_reader.hpp"
#include "project/project.hpp"

namespace frostwall::project::detail {

// "survey": {"file", "pipe_depth"}; the file relative to base_directory
// (the project file's folder; empty: the working directory). Each problem
// of the file names it and its line.
std::optional<Survey> read_survey(const Node& n, const Layout& layout, const std::string& base_directory);
// "sections": {"depths": [...]} or {"every": metres}.
Sections read_sections(const Node& n);
// "failed_pipes": [k, ...], pipe numbers from 1.
std::vector<int> read_failed_pipes(const Node& n, const Layout& layout);

}  // namespace frostwall::project::detail
