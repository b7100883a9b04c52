// A shaft's sections (its layers or as-built depths) with a freezing plant:
// not independent variants but cross-sections of one circuit, whose brine
// warms down the pipes with what each section draws. They run together
// (freezing/plant_run.hpp), side by side between the brine's exchanges on
// the machine's cores, on the first rank alone under mpirun. The outcome
// has the form a study's run has (each section's folder, summary and
// report), with the plant's summary block beside it and plant.csv in the
// project's output directory.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "study/run_study.hpp"

namespace frostwall::study {

struct CoupledRun {
  StudyRun run;
  nlohmann::json plant;  // the summary's `plant` (with `sections` in the variants' order)
};

// depths[k]: the depth of the study's variant k on the pipe (any order).
CoupledRun run_coupled(const project::Project& p, const Study& study, const std::vector<double>& depths,
                       const StudyOptions& options);

}  // namespace frostwall::study
