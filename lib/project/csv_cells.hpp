// The cells of one line of a CSV file the project names (survey, readings),
// for the readers of lib/project. Internal to lib/project.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frostwall::project::detail {

// The comma-separated cells of a line, each trimmed of blanks.
std::vector<std::string> split_cells(const std::string& line);
// A finite number filling the whole cell; nullopt otherwise.
std::optional<double> parse_number(const std::string& cell);
// A line with nothing but blanks.
bool blank_line(const std::string& line);
// A file the project names, relative to its folder (base_directory; empty:
// the working directory) unless absolute.
std::string resolve_path(const std::string& file, const std::string& base_directory);

}  // namespace frostwall::project::detail
