#include "study/excavation_overview.hpp"

#include "freezing/excavation_run.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

using nlohmann::json;

void sink_at(json& doc, double depth, std::optional<double> day) {
  if (!doc.contains("excavation")) return;
  doc["excavation"]["depth"] = depth;
  if (day) doc["excavation"]["days"] = json::array({*day});
}

json excavation_overview(const std::vector<json>& summaries, const std::vector<std::string>& names) {
  std::vector<json> entries;
  for (const auto& s : summaries) entries.push_back(s.value(summary::keys::excavation, json::object()));
  return freezing::excavation_overview(entries, names);
}

}  // namespace frostwall::study
