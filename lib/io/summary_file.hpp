// summary.json of an output directory: the one place it is written (every
// engine, the error estimate, calibration, layered, as-built and
// failed-pipe summaries) and read back (`frostwall report DIR`).
#pragma once

#include <filesystem>

#include "summary/summary.hpp"

namespace frostwall::io {

// Writes <directory>/summary.json atomically, indented by two.
void write_summary(const std::filesystem::path& directory, const summary::Summary& s);

// Reads <directory>/summary.json; throws std::runtime_error when it is
// missing, not JSON, or holds a typed key of another type.
summary::Summary read_summary(const std::filesystem::path& directory);

}  // namespace frostwall::io
