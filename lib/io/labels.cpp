#include "io/labels.hpp"

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

namespace frostwall::io {

Labels file_labels(const project::Project& p, const char* time_unit) {
  return {{"project", p.name},
          {"time_unit", time_unit ? time_unit : p.time.unit_name()},
          {"frostwall_version", FROSTWALL_VERSION}};
}

void add_labels(vtkFieldData& data, const Labels& labels) {
  for (const auto& [name, text] : labels) {
    vtkNew<vtkStringArray> array;
    array->SetName(name.c_str());
    array->InsertNextValue(text);
    data.AddArray(array);
  }
}

}  // namespace frostwall::io
