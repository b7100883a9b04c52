// The output directory of a run, checked before any work.
#pragma once

#include <string>

namespace frostwall::io {

// Throws project::ProjectError naming output.directory when it cannot be
// created (a file in its path, no permission, a file system that refuses):
// it is made and removed again, so nothing is left behind.
void check_output_directory(const std::string& directory);

}  // namespace frostwall::io
