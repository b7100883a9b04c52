// The study page's part for CFD-DEM variants (the leak over a cavity at
// several Darcy velocities, issue 16): a table of what each variant lost
// and how the ground settled, and the curves of all variants overlaid.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "study/run_study.hpp"

namespace frostwall::study {

// Any finished variant is a CFD-DEM run.
bool has_erosion(const StudyRun& run);
// Adds has_erosion, erosion_rows and the charts to the study view.
void add_erosion(const StudyRun& run, nlohmann::json& view);
void write_erosion_csv(const std::filesystem::path& file, const StudyRun& run);

}  // namespace frostwall::study
