#include "study/run_layers.hpp"
#include "study/excavation_overview.hpp"

#include <fmt/core.h>
#include <limits>

#include "io/output_directory.hpp"
#include "run/check_project.hpp"
#include "study/run_coupled.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;
using nlohmann::json;
namespace keys = summary::keys;

std::string layer_folder(const std::string& name) {
  std::string folder;
  for (char c : name) folder += variant_name_character(c) ? c : '_';
  if (folder.empty() || folder.front() == '.') folder.insert(folder.begin(), 'L');
  return folder;
}

std::size_t governing_layer(const std::vector<json>& summaries) {
  std::size_t governing = 0;
  double latest = -1.0, worst = -1.0;
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    const json design = summaries[k].value(keys::design, json::object());
    const json met = design.value(keys::met_day, json());
    const double day = met.is_number() ? met.get<double>() : std::numeric_limits<double>::infinity();
    const json wall = summaries[k].value(keys::wall, json::array());
    const json u = wall.empty() ? json() : wall.back().value(keys::utilisation, json());
    const double utilisation = u.is_number() ? u.get<double>() : std::numeric_limits<double>::infinity();
    if (day > latest || (day == latest && utilisation > worst)) governing = k, latest = day, worst = utilisation;
  }
  return governing;
}

std::vector<json> layer_documents(const project::Project& p, const std::string& project_text) {
  const fs::path out = p.output.directory;
  const json base = json::parse(project_text);
  std::vector<json> docs;
  for (const auto& layer : p.layers) {
    json doc = base;
    doc.merge_patch(json::parse(layer.patch));
    const std::size_t k = docs.size();
    sink_at(doc, layer.depth,
            p.excavation && !p.excavation->days.empty() ? std::optional(p.excavation->days[k]) : std::nullopt);
    doc["output"]["directory"] = (out / layer_folder(layer.name)).string();
    project::parse_project(doc.dump(), "layers: " + layer.name);  // every layer loads before any runs
    docs.push_back(std::move(doc));
  }
  return docs;
}

std::vector<std::string> check_layers(const project::Project& p, const std::string& project_text) {
  io::check_output_directory(p.output.directory);
  const auto docs = layer_documents(p, project_text);
  std::vector<std::string> lines{fmt::format("layers: {} cross-sections, one run each", docs.size())};
  for (std::size_t k = 0; k < docs.size(); ++k)
    for (const auto& line : run::check_project(project::parse_project(docs[k].dump(), "layers: " + p.layers[k].name)))
      lines.push_back(p.layers[k].name + ": " + line);
  return lines;
}

StudyRun run_layers(const project::Project& p, const std::string& project_text, const StudyOptions& options) {
  io::check_output_directory(p.output.directory);
  const fs::path out = p.output.directory;
  Study study;
  study.name = p.name;
  study.output_directory = out;
  study.estimate_errors = false;  // as the project says: a layered run is no study
  const auto docs = layer_documents(p, project_text);
  // Made before the layers run side by side: each layer's own check makes
  // and removes only its folder, never this shared parent under another.
  fs::create_directories(out);
  for (std::size_t k = 0; k < docs.size(); ++k)
    study.variants.push_back({layer_folder(p.layers[k].name), p.layers[k].name, docs[k]});
  // With a plant the layers are sections of one brine circuit, run together.
  std::vector<double> depths;
  for (const auto& layer : p.layers) depths.push_back(layer.depth);
  CoupledRun coupled;
  if (p.plant) coupled = run_coupled(p, study, depths, options);
  StudyRun run = p.plant ? std::move(coupled.run) : run_study(study, options);
  if (!run.writer) return run;
  std::vector<json> summaries;
  for (std::size_t k = 0; k < run.variants.size(); ++k) {
    const auto& v = run.variants[k];
    if (!v.ok)
      throw std::runtime_error(
          fmt::format("layer '{}': {}", p.layers[k].name, v.errors.empty() ? "failed" : v.errors.front()));
    summaries.push_back(v.summary);
  }
  // The layered summary: the governing layer's, with every layer's beside it.
  const std::size_t g = governing_layer(summaries);
  json summary = summaries[g];
  summary[keys::project] = p.name;
  summary[keys::governing_layer] = p.layers[g].name;
  summary[keys::layers] = json::array();
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    json entry = summaries[k];
    entry["layer"] = {{"name", p.layers[k].name},
                      {"depth", p.layers[k].depth},
                      {"soil", p.layers[k].soil.name},
                      {"pressure_MPa", p.layers[k].pressure},
                      {"directory", layer_folder(p.layers[k].name)},
                      {"governing", k == g}};
    if (p.plant) entry["layer"]["brine_temperature"] = coupled.plant["sections"][k]["brine_temperature"];
    summary[keys::layers].push_back(std::move(entry));
  }
  if (p.plant) summary[keys::plant] = coupled.plant;
  if (p.excavation) {
    std::vector<std::string> names;
    for (const auto& layer : p.layers) names.push_back(layer.name);
    summary[keys::excavation] = excavation_overview(summaries, names);
  }
  write_joined_run(p, project_text, summary);
  return run;
}

}  // namespace frostwall::study
