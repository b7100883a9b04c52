// What every VTK file says about itself in its field data: the project's
// name, the unit of the times in its .pvd collection, and the frostwall
// version that wrote it (string arrays, shown in ParaView's Information
// panel and readable with GetFieldData()).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "project/project.hpp"

class vtkFieldData;

namespace frostwall::io {

using Labels = std::vector<std::pair<std::string, std::string>>;

// project, time_unit (the project's, or the one given: s, h or d),
// frostwall_version.
Labels file_labels(const project::Project& p, const char* time_unit = nullptr);

void add_labels(vtkFieldData& data, const Labels& labels);

}  // namespace frostwall::io
