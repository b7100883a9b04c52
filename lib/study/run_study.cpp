#include "study/run_study.hpp"

#include <chrono>
#include <cstdlib>
#include <fmt/core.h>
#include <mutex>
#include <omp.h>
#include <thread>

#include "particles/side_by_side.hpp"
#include "io/atomic_file.hpp"
#include "io/summary_file.hpp"
#include "project/project.hpp"
#include "report/report.hpp"
#include "run/run_project.hpp"
#include "study/ranks.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;

namespace {

VariantOutcome run_variant(const Variant& v, bool estimate_errors,
                           const std::function<void(const std::string&)>& note) {
  const auto start = std::chrono::steady_clock::now();
  VariantOutcome out;
  out.name = v.name;
  out.changes = v.changes;
  out.directory = v.project["output"]["directory"].get<std::string>();
  // Variants are ranked with their error bars: the estimate is on unless
  // the project turns it off (CFD-DEM runs have none).
  nlohmann::json project = v.project;
  if (estimate_errors && project.value("physics", std::string()) != "cfd-dem" &&
      !(project.contains("numerics") && project["numerics"].contains("error_estimate")))
    project["numerics"]["error_estimate"] = true;
  const std::string text = project.dump(2) + "\n";
  try {
    const project::Project p = project::parse_project(text, v.name);
    run::RunOptions options;
    options.project_text = text;
    options.note = [&](const std::string&) {};  // the wedge notes of every variant would only clutter
    out.summary = summary::to_json(run::run_project(p, options));
    if (p.output.report) report::write_report(out.directory);  // from the files just written
    out.ok = true;
  } catch (const project::ProjectError& e) {
    out.errors = e.problems();
  } catch (const std::exception& e) {
    out.errors = {std::string("run failed: ") + e.what()};
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (note)
    note(out.ok ? fmt::format("{}: done in {:.1f} s", v.name, out.seconds)
                : fmt::format("{}: FAILED: {}", v.name, out.errors.empty() ? "" : out.errors.front()));
  return out;
}

nlohmann::json outcome_json(const VariantOutcome& v) {
  return {{"name", v.name},      {"changes", v.changes}, {"directory", v.directory.string()},
          {"ok", v.ok},          {"errors", v.errors},   {"summary", v.summary},
          {"seconds", v.seconds}};
}

VariantOutcome outcome_of(const nlohmann::json& j) {
  VariantOutcome v;
  v.name = j["name"];
  v.changes = j["changes"];
  v.directory = j["directory"].get<std::string>();
  v.ok = j["ok"];
  v.errors = j["errors"].get<std::vector<std::string>>();
  v.summary = j["summary"];
  v.seconds = j["seconds"];
  return v;
}

}  // namespace

StudyRun run_study(const Study& study, const StudyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  StudyRun result;
  // CFD-DEM variants run one after another, on every rank together: each
  // embeds LAMMPS on the process's MPI communicator, which two threads may
  // not share; they also share one settled packing (the first variant
  // settles it).
  bool grains = false;
  for (const auto& v : study.variants) grains |= v.project.value("physics", std::string()) == "cfd-dem";
  const Ranks ranks = grains ? Ranks{} : world_ranks();
  result.ranks = ranks.size;
  const char* env_rank = std::getenv("OMPI_COMM_WORLD_RANK");
  result.writer = grains ? (env_rank == nullptr || std::string(env_rank) == "0") : ranks.first();
  std::vector<std::size_t> mine;
  for (std::size_t k = static_cast<std::size_t>(ranks.rank); k < study.variants.size();
       k += static_cast<std::size_t>(ranks.size))
    mine.push_back(k);
  // This rank's share of the machine: all of it, or its part when ranks
  // share the node and are not bound to cores of their own.
  int cores = particles::usable_cores();
  const int machine = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (ranks.size > 1 && cores >= machine) cores = std::max(1, cores / ranks.on_this_node);
  const int n = static_cast<int>(mine.size());
  result.jobs = std::clamp(options.jobs > 0 ? options.jobs : cores, 1, std::max(1, n));
  if (grains) result.jobs = 1;
  result.threads = options.threads > 0 ? options.threads
                                       : (result.jobs == 1 ? (ranks.size > 1 ? cores : omp_get_max_threads()) : 1);
  result.variants.resize(study.variants.size());

  std::mutex note_lock;
  auto note = [&](const std::string& line) {
    if (!options.note) return;
    std::lock_guard lock(note_lock);
    options.note(ranks.size > 1 ? fmt::format("rank {}: {}", ranks.rank, line) : line);
  };
  particles::side_by_side(mine.size(), result.jobs, result.threads, [&](std::size_t i) {
    result.variants[mine[i]] = run_variant(study.variants[mine[i]], study.estimate_errors, note);
  });
  if (ranks.size > 1) {
    // Every rank's outcomes to every rank, back in the study's order.
    std::vector<std::string> texts;
    for (const auto k : mine) texts.push_back(outcome_json(result.variants[k]).dump());
    const auto shared = share_texts(ranks, texts);
    for (int r = 0; r < ranks.size; ++r)
      for (std::size_t i = 0; i < shared[r].size(); ++i)
        result.variants[static_cast<std::size_t>(r) + i * static_cast<std::size_t>(ranks.size)] =
            outcome_of(nlohmann::json::parse(shared[r][i]));
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

void write_joined_run(const project::Project& p, const std::string& project_text, const nlohmann::json& summary) {
  const fs::path out = p.output.directory;
  io::write_text_file(out / "project.json", project_text);
  io::write_summary(out, summary::from_json(summary));
  if (p.output.report) report::write_report(out);
}

}  // namespace frostwall::study
