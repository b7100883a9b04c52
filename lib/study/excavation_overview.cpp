#include "study/excavation_overview.hpp"

#include "summary/summary.hpp"

namespace frostwall::study {

using nlohmann::json;

void sink_at(json& doc, double depth, std::optional<double> day) {
  if (!doc.contains("excavation")) return;
  doc["excavation"]["depth"] = depth;
  if (day) doc["excavation"]["days"] = json::array({*day});
}

json excavation_overview(const std::vector<json>& summaries, const std::vector<std::string>& names) {
  json sections = json::array();
  std::optional<std::size_t> critical;
  // Ranked by the smallest margin; sections without one by the thinnest wall.
  auto key = [&](std::size_t k) {
    const json& e = sections[k];
    return e["margin_min"].is_number()       ? std::make_pair(0, e["margin_min"].get<double>())
           : e["thinnest_after"].is_number() ? std::make_pair(1, e["thinnest_after"].get<double>())
                                             : std::make_pair(2, 0.0);
  };
  for (std::size_t k = 0; k < summaries.size(); ++k) {
    json entry = summaries[k].value(summary::keys::excavation, json::object());
    entry.erase("sections");
    entry.erase("critical_depth");
    entry["name"] = names[k];
    sections.push_back(entry);
    if (key(k).first < 2 && (!critical || key(k) < key(*critical))) critical = k;
  }
  json overview = {{"sections", sections}};
  if (!critical) {
    overview["critical_depth"] = nullptr;
    return overview;
  }
  const json& c = sections[*critical];
  overview["critical_depth"] = c["depth"];
  overview["critical_section"] = c["name"];
  overview["critical_day"] = c["margin_min"].is_number() ? c["margin_min_day"] : c["thinnest_after_day"];
  overview["margin_min"] = c["margin_min"];
  return overview;
}

}  // namespace frostwall::study
