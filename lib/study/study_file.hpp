// The study file: a base project and its variants, as named overrides (JSON
// merge patches, RFC 7386) and/or a cartesian product of parameter lists.
// Read and checked completely before anything runs, like a project file:
// every problem is one line naming its JSON path.
//
//   { "name": "Layouts", "base": "single_ring_sand.json",        // relative to the study file
//     "output": { "directory": "out/study_layouts" },
//     "patch": { "numerics": { "spacing": 0.05 } },              // optional: every variant
//     "variants": [ { "name": "three-hole", "patch": { ... } } ], // optional
//     "product": [ { "path": "soil", "values": ["sand", "clay"] },// optional
//                  { "path": "pipe.temperature", "values": [-20, -30], "labels": ["T20", "T30"] } ],
//     "rank": { "thickness_day": 60 } }                           // optional
//
// Variants = overrides x product combinations (either alone when the other
// is absent); a name joins the override's name and the value labels with '+'.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "project/input_error.hpp"

namespace frostwall::study {

struct Variant {
  std::string name;        // also its output folder
  std::string changes;     // what differs from the base, one line
  nlohmann::json project;  // the project file of this run (output redirected, report on)
};

struct Study {
  std::string name;
  std::string description;
  std::filesystem::path base;  // the base project file as resolved
  std::filesystem::path output_directory;
  double thickness_day = 0.0;  // thickness ranking day (default: the base's last snapshot)
  std::vector<Variant> variants;
  // A study ranks with error bars: numerics.error_estimate is on in every
  // variant that does not set it. The layers of a layered project (run as
  // a study, one variant per layer) keep the project's own setting.
  bool estimate_errors = true;
};

// Every problem of a study file, "json.path: what is wrong", one per line.
class StudyError : public project::InputError {
 public:
  using InputError::InputError;
};

// Reads the study file and the base project it names (as JSON: a variant's
// project is checked when that variant runs, so one bad variant fails alone).
Study load_study(const std::string& path);
// The same from text; `directory` resolves "base", `source` names the text.
Study parse_study(const std::string& text, const std::filesystem::path& directory, const std::string& source = "study");

// A name usable as a folder and in a link: letters, digits and . _ - + =,
// not starting with '.'.
bool valid_variant_name(const std::string& name);
// One character such a name may hold.
bool variant_name_character(char c);

}  // namespace frostwall::study
