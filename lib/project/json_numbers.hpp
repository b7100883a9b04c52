// Numbers read back from JSON a run wrote (summary.json and the like),
// where a number may be missing, null or something else.
#pragma once

#include <limits>

namespace frostwall::project {

// The number v holds (nlohmann::json or ordered_json); NaN for anything
// else.
template <class J>
double number_or_nan(const J& v) {
  return v.is_number() ? v.template get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace frostwall::project
