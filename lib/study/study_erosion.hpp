// The study page's part for CFD-DEM variants (the leak over a cavity at
// several Darcy velocities): a table of what each variant lost
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
// Variants that differ only by their packing's seed (a `...seed` path in
// their changes): per such group of two or more, the mean and the sample
// standard deviation over the seeds of the grains lost, the crater depth
// and the deepest settlement ("8816 ± 25"). A different packing is not a
// coarser grid: this spread is what CFD-DEM runs have for an error bar.
nlohmann::json seed_spread(const StudyRun& run);
void write_erosion_csv(const std::filesystem::path& file, const StudyRun& run);

}  // namespace frostwall::study
