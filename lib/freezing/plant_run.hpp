// A project's freezing plant: its shaft sections (the layers, the as-built
// depths, or the one section of a plain shaft project at mid-pipe) coupled
// through the brine of its coaxial pipes (brine_sections.hpp), with the
// plant's supply or capacity, the built-in or given brine, and the pipes
// that carry flow (failed ones carry none). Writes plant.csv; returns the
// sections' summaries and the summary's `plant` block.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "freezing/brine_sections.hpp"

namespace frostwall::freezing {

struct PlantSection {
  std::string name;  // the layer's, or the depth's
  CircuitSection section;
};

struct PlantOutcome {
  std::vector<summary::Summary> sections;
  nlohmann::ordered_json plant;  // the summary's `plant`
};

// The circuit's settings from the project's plant and shaft section.
CircuitSettings circuit_settings(const project::Project& p);

// p: the project that holds the plant (its pipes and time); out: where
// plant.csv goes.
PlantOutcome run_plant(const project::Project& p, const std::vector<PlantSection>& sections,
                       const project::RunOptions& options, const std::filesystem::path& out);

// A shaft project's one section in its plant's circuit: at mid-pipe.
CircuitSection mid_pipe_section(const project::Project& p, const std::string& project_text,
                                RunExtension* extension = nullptr);

// The shaft project's single section with its plant, into its own output
// directory (summary.json then carries `plant`).
summary::Summary run_single_plant(const project::Project& p, const project::RunOptions& options);

}  // namespace frostwall::freezing
