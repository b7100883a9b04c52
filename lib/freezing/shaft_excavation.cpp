// The shaft results' readings after the section's excavation
// (ShaftResults::set_face, ShaftResults::excavation_entry).
#include <algorithm>
#include <cmath>
#include <limits>

#include "freezing/shaft_results.hpp"
#include "summary/summary.hpp"

namespace frostwall::freezing {

void ShaftResults::set_face(const ExcavationRun& excavation) {
  fan_gauge_->set_inner_limit(excavation.face_radius());
  planes_gauge_->set_inner_limit(excavation.face_radius());
  excavation_ = &excavation;
}

nlohmann::json ShaftResults::excavation_entry(double day) const {
  using nlohmann::json;
  const auto& design = project_.design;
  json series = json::array();
  std::optional<double> thinnest, thinnest_day, margin_min, margin_min_day;
  std::vector<Reading> after;
  for (const auto* readings : {&series_, &event_readings_})
    for (const auto& r : *readings)
      if (r.day >= day - 1e-9) after.push_back(r);
  std::stable_sort(after.begin(), after.end(), [](const Reading& a, const Reading& b) { return a.day < b.day; });
  for (const auto& r : after) {
    const double thickness = design.isotherm ? r.isotherm_thickness.value_or(0.0) : r.min_thickness;
    const auto mean = design.isotherm ? r.isotherm_mean_temperature : r.mean_temperature_thinnest;
    std::optional<double> required = design.required_thickness;
    if (design.checks_strength()) required = check(r).required;
    // A strength the wall cannot reach at any thickness (an elastic formula
    // past its limit) has no finite margin: -infinity, shown as null.
    double margin = std::numeric_limits<double>::quiet_NaN();  // no requirement
    if (required) margin = thickness - *required;
    else if (design.checks_strength()) margin = -std::numeric_limits<double>::infinity();
    series.push_back({{"day", r.day},
                      {"days_after", r.day - day},
                      {"thickness", thickness},
                      {"mean_temperature", summary::number_or_null(mean)},
                      {"required_thickness", summary::number_or_null(required)},
                      {"margin", std::isfinite(margin) ? json(margin) : json(nullptr)}});
    if (!thinnest || thickness < *thinnest) thinnest = thickness, thinnest_day = r.day;
    if (!std::isnan(margin) && (!margin_min || margin < *margin_min)) margin_min = margin, margin_min_day = r.day;
  }
  const bool finite = margin_min && std::isfinite(*margin_min);
  return {{"thinnest_after", summary::number_or_null(thinnest)},
          {"thinnest_after_day", summary::number_or_null(thinnest_day)},
          {"margin_min", finite ? json(*margin_min) : json(nullptr)},
          {"margin_min_day", summary::number_or_null(margin_min_day)},
          {"carried", margin_min ? json(*margin_min >= 0.0) : json(nullptr)},
          {"measured_on", design.isotherm ? "isotherm" : "frozen front"},
          {"series", series}};
}

}  // namespace frostwall::freezing
