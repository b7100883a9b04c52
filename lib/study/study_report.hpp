// What a study leaves at the top of its output folder: study.csv (one row
// per variant, both rankings) and study.html (ranked tables, the variants'
// thickness curves overlaid, links to each variant's report.html).
#pragma once

#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "study/run_study.hpp"

namespace frostwall::study {

// One variant's figures for the rankings.
struct Standing {
  const VariantOutcome* variant = nullptr;
  std::optional<double> closure_day;
  double closure_error = std::numeric_limits<double>::quiet_NaN();  // its estimated error (d); NaN: none
  // Closed within the combined error (the two errors added) of the variant
  // ranked just before it: the same closure rank, and marked as tied.
  bool closure_tied = false;
  double thickness = std::numeric_limits<double>::quiet_NaN();         // thinnest wall at the ranking day (m)
  double mean_temperature = std::numeric_limits<double>::quiet_NaN();  // on OB at that day (degC)
  int closure_rank = 0, thickness_rank = 0;                            // 1 = best; 0 = not ranked (failed)
};

// In closure order: closed variants by day, then those that never closed
// (thickest first), then failed ones. A closed variant whose day differs
// from the one ranked before it by less than their two errors added is
// tied with it: it takes that variant's rank.
std::vector<Standing> rank_variants(const StudyRun& run, double thickness_day);

void write_study_csv(const std::filesystem::path& file, const std::vector<Standing>& standings, double thickness_day);

nlohmann::json study_view(const Study& study, const StudyRun& run, const std::vector<Standing>& standings);
void write_study_html(const std::filesystem::path& file, const Study& study, const StudyRun& run,
                      const std::vector<Standing>& standings);

}  // namespace frostwall::study

namespace frostwall::study {

// The whole study: runs every variant, then writes study.csv and study.html
// into the study's output folder (created).
StudyRun run_and_write_study(const Study& study, const StudyOptions& options);

}  // namespace frostwall::study
