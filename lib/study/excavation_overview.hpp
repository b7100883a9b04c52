// A shaft's excavation over its sections (layers or as-built depths): each
// section's project file sinks at its own depth, and the shaft's summary
// gathers every section's excavation entry and names the critical one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace frostwall::study {

// The section's project file sinks at `depth`, on `day` when the project
// gives the days section by section. No change without "excavation".
void sink_at(nlohmann::json& doc, double depth, std::optional<double> day);

// The shaft's `excavation` from its sections' summaries
// (freezing::excavation_overview); summaries[k]: section k's, names[k] its name.
nlohmann::json excavation_overview(const std::vector<nlohmann::json>& summaries, const std::vector<std::string>& names);

}  // namespace frostwall::study
