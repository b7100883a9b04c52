// Sinking the shaft inside the frozen wall (project "excavation"): on its
// day each section's ground inside the excavation radius is taken out, the
// face meets the shaft's air through a film, and later a lining of its own
// material (with the heat its cement gives off as it sets) covers the face.
// docs/reference/excavation.md.
#pragma once

#include <optional>
#include <vector>

#include "project/schedule.hpp"

namespace frostwall::project {

// The heat the lining's cement gives off as it sets, J/kg released by a
// time after placing: Q (1 - exp(-t / tau)), or a table [day, J/kg] read
// linearly from 0 at placing and held after its last point.
struct HydrationHeat {
  double total = 0.0;         // J/kg (exponential form)
  double release_time = 0.0;  // s, tau (exponential form)
  // Table form: (s since placing, J/kg), from (0, 0); empty: the exponential form.
  TemperatureSchedule released;
  double at(double seconds_since_placing) const;  // J/kg released so far
  double final() const;                           // J/kg once it has all been released
  double end_time() const;                        // s by which (all but 1e-6 of) it is released
};

struct Lining {
  double thickness = 0.0;      // m, inward from the excavation radius
  double conductivity = 0.0;   // W/(m K)
  double heat_capacity = 0.0;  // J/(kg K)
  double density = 0.0;        // kg/m3
  HydrationHeat hydration;
  double placed_after = 0.0;                    // s after the section is excavated
  std::optional<double> placement_temperature;  // degC; none: the air's on the day
};

struct Excavation {
  double start_day = 0.0;
  std::optional<double> rate;  // m/day
  std::vector<double> days;    // one per section (as given), or empty with a rate
  double depth = 0.0;          // m: this section's depth (a layer or an as-built section sets its own)
  TemperatureSchedule air_temperature;
  double heat_transfer = 0.0;  // W/(m2 K), air to face
  std::optional<Lining> lining;
  // The day this section is excavated: its own entry of `days`, else the
  // start day plus its depth at the sinking rate.
  double day() const { return days.empty() ? start_day + depth / rate.value_or(1.0) : days.front(); }
};

}  // namespace frostwall::project
