// What a plant's run tells (plant_run.hpp): plant.csv, every exchange's
// load, supply and return with each section's brine and draw; and the
// summary's `plant` block: the sizing figures (peak load, load at the end,
// energy, electricity with a COP), the brine and its films, each section's
// brine, a thinned series and the brine along the pipe at the snapshots.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "freezing/brine_sections.hpp"

namespace frostwall::freezing {

struct PlantSection;

void write_plant_csv(const std::filesystem::path& file, const std::vector<std::string>& names, const CircuitRun& run);

nlohmann::ordered_json plant_summary(const project::Project& p, const CircuitSettings& settings,
                                     const std::vector<PlantSection>& sections, const CircuitRun& run);

}  // namespace frostwall::freezing
