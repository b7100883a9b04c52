// What the caller of a run asks of it, whatever the engine: progress, notes
// for the user, and the project file's text to keep beside the results.
#pragma once

#include <functional>
#include <string>

namespace frostwall::project {

struct RunOptions {
  // Called after every step with (t, t_end) in seconds; may be empty.
  std::function<void(double, double)> progress;
  // Called with one-line notes worth telling the user (wedge chosen, spacing fitted).
  std::function<void(const std::string&)> note;
  // The project file's text as given; written as project.json so that the
  // report can be rebuilt from the output directory alone. May be empty.
  std::string project_text;
};

}  // namespace frostwall::project
