#include "study/run_coupled.hpp"

#include <algorithm>
#include <chrono>
#include <fmt/core.h>
#include <numeric>

#include "freezing/plant_run.hpp"
#include "report/report.hpp"
#include "study/ranks.hpp"

namespace frostwall::study {

CoupledRun run_coupled(const project::Project& p, const Study& study, const std::vector<double>& depths,
                       const StudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CoupledRun out;
  out.run.writer = world_ranks().first();
  out.run.variants.resize(study.variants.size());
  if (!out.run.writer) return out;  // one circuit, one process
  // The circuit takes its sections from the top down.
  std::vector<std::size_t> order(depths.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return depths[a] < depths[b]; });
  std::vector<freezing::PlantSection> sections;
  for (const auto k : order) {
    const auto& v = study.variants[k];
    const std::string text = v.project.dump(2) + "\n";
    sections.push_back({v.changes, {project::parse_project(text, v.name), depths[k], text}});
  }
  project::RunOptions run_options;
  run_options.note = [](const std::string&) {};
  if (options.note)
    options.note(
        fmt::format("plant: {} sections coupled through the brine, side by side between exchanges", sections.size()));
  auto outcome = freezing::run_plant(p, sections, run_options, p.output.directory);
  out.plant = outcome.plant;
  out.plant["sections"] = nlohmann::json::array();  // in the variants' order
  for (std::size_t i = 0; i < order.size(); ++i) {
    out.plant["sections"][order[i]] = outcome.plant["sections"][i];
    const auto& v = study.variants[order[i]];
    auto& o = out.run.variants[order[i]];
    o.name = v.name, o.changes = v.changes, o.ok = true;
    o.directory = v.project["output"]["directory"].get<std::string>();
    o.summary = summary::to_json(outcome.sections[i]);
    if (v.project["output"].value("report", true)) report::write_report(o.directory);
  }
  out.run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double each = out.run.seconds / static_cast<double>(order.size());
  for (auto& v : out.run.variants) v.seconds = each;
  if (options.note) options.note(fmt::format("plant: done in {:.1f} s", out.run.seconds));
  return out;
}

}  // namespace frostwall::study
