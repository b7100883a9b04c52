// Running a study's variants: each is a whole project run with its own
// folder and report. Variants run side by side, one OpenMP thread each
// (the default, measured faster on this kind of machine: see README), or
// one after another with every thread inside each run. A variant that
// fails is recorded with its error; the others go on. Under mpirun the
// variants are spread over the ranks (study/ranks.hpp), each rank's share
// run as above on its part of the machine, and every rank ends with every
// outcome; rank 0 writes what joins them.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "project/project.hpp"
#include "study/study_file.hpp"

namespace frostwall::study {

struct VariantOutcome {
  std::string name, changes;
  std::filesystem::path directory;
  bool ok = false;
  std::vector<std::string> errors;  // bad variant input (one line per problem) or the run's failure
  nlohmann::json summary;           // the summary a finished run wrote (summary::to_json)
  double seconds = 0.0;             // wall time of this variant
};

struct StudyOptions {
  int jobs = 0;                                  // variants at once; 0 = one per core (at most the variant count)
  int threads = 0;                               // OpenMP threads per variant; 0 = all cores when jobs = 1, else 1
  std::function<void(const std::string&)> note;  // progress lines (thread-safe calls)
};

struct StudyRun {
  std::vector<VariantOutcome> variants;  // in the study's order
  int jobs = 1, threads = 1;
  int ranks = 1;       // MPI ranks the variants were spread over
  bool writer = true;  // this process writes the files that join the variants
  double seconds = 0.0;
};

StudyRun run_study(const Study& study, const StudyOptions& options);

// What joins a layered, as-built or failed-pipe run's variants, beside
// them in p.output.directory: project.json (the file as given), `summary`
// as summary.json and, with output.report, the report.
void write_joined_run(const project::Project& p, const std::string& project_text, const nlohmann::json& summary);

}  // namespace frostwall::study
