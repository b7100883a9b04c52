// The study page's part for shaft variants under seepage (the same ring at
// several regional Darcy fluxes): closure against the
// flux in one chart, still water at 0, and a table of each variant's
// closure, last gap and its side, the wall's thinnest upstream and
// downstream, and the verdict.
#pragma once

#include <nlohmann/json.hpp>

#include "study/run_study.hpp"

namespace frostwall::study {

// Any finished variant carries a groundwater block.
bool has_seepage(const StudyRun& run);
// Adds has_seepage, seepage_rows and seepage_chart_svg to the study view.
void add_seepage(const StudyRun& run, nlohmann::json& view);

}  // namespace frostwall::study
