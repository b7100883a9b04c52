// The error an input file (a project, a study) is refused with.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace frostwall::project {

// Every problem found in an input file, one line each, in the form
// "json.path: what is wrong"; what() is the lines joined by newlines.
class InputError : public std::runtime_error {
 public:
  explicit InputError(std::vector<std::string> problems);
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

}  // namespace frostwall::project
