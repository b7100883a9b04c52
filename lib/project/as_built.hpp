// The shaft as built: where each freeze pipe runs with depth (a borehole
// survey), the depths at which the section is checked, and which pipes
// are off. Plain structs read by lib/project; lib/geometry turns a survey
// into pipe traces (geometry/survey.hpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frostwall::project {

// The two forms of a survey file, told apart by its header.
enum class SurveyForm {
  positions,  // pipe,depth,x,y: as-built centres (m, the layout's frame) at vertical depths
  stations,   // pipe,depth,inclination_deg,azimuth_deg: measured depth along the hole, from the collar
};

// One row of the survey file.
struct SurveyRow {
  int line = 0;        // in the file (the header is line 1)
  double depth = 0.0;  // m
  double a = 0.0;      // x (m) or inclination (deg, from the vertical)
  double b = 0.0;      // y (m) or azimuth (deg, clockwise from +y)
};

struct Survey {
  std::string file;  // as written in the project (for messages)
  std::string path;  // resolved against the project file's folder
  SurveyForm form = SurveyForm::positions;
  std::vector<std::vector<SurveyRow>> pipes;  // [pipe number - 1], rows by increasing depth
  // Vertical depth of every pipe's bottom; nullopt: each pipe ends at the
  // depth of its last row.
  std::optional<double> pipe_depth;
};

// Where the section is checked: explicit depths, or every `every` metres;
// neither: every layer's depth and the depth of the largest gap in each
// layer's range (or in the whole shaft without layers).
struct Sections {
  std::vector<double> depths;  // m, as given
  std::optional<double> every;
};

}  // namespace frostwall::project
