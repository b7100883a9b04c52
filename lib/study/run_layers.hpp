// A shaft through several layers of ground: one cross-section per
// layer, run side by side as a study's variants (run_study.hpp), each into
// its own folder <output>/<layer>. Then the layered summary.json beside them:
// the governing layer's summary (the layer the design waits longest for)
// with `layers`, one summary per layer, and `governing_layer`; and the
// report, built from the governing layer's files with a table by layer.
#pragma once

#include <string>

#include "project/project.hpp"
#include "study/run_study.hpp"

namespace frostwall::study {

// The layer's folder name: its name with every character a variant name
// may not hold (study_file.hpp) replaced by '_'.
std::string layer_folder(const std::string& layer_name);

// The index of the governing layer among layer summaries: the one met last
// (never met counts as latest), ties to the higher utilisation on the last
// snapshot.
std::size_t governing_layer(const std::vector<nlohmann::json>& summaries);

// project_text: the project file as given (each layer's run records its
// own, patched). Throws project::ProjectError for a layer project that
// does not load (before anything runs) and std::runtime_error when a
// layer's run fails.
// Each layer's project file: the base patched by the layer, its output in
// <output>/<layer>; throws project::ProjectError for one that does not load.
std::vector<nlohmann::json> layer_documents(const project::Project& project, const std::string& project_text);
// `frostwall check` on a layered project: every layer checked as
// run::check_project checks one cross-section; its lines prefixed by the layer's name.
std::vector<std::string> check_layers(const project::Project& project, const std::string& project_text);

StudyRun run_layers(const project::Project& project, const std::string& project_text, const StudyOptions& options);

}  // namespace frostwall::study
