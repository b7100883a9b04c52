// report.html: the self-contained HTML report of one run (project, headline,
// temperature maps, charts, run facts), built from the files the run left
// in its output directory, so it can be rebuilt later (`frostwall report`).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace frostwall::report {

// The data the template is rendered with (tests look at it).
nlohmann::json report_view(const std::filesystem::path& dir);

// report.html's text. Throws std::runtime_error when summary.json is
// missing or unreadable.
std::string render_report(const std::filesystem::path& dir);

// Writes <dir>/report.html (temporary name, then renamed); returns its path.
std::filesystem::path write_report(const std::filesystem::path& dir);

}  // namespace frostwall::report
