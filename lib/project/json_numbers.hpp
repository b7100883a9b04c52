// Numbers read back from JSON a run wrote (summary.json and the like),
// where a number may be missing, null or something else.
#pragma once

#include <limits>
#include <optional>

namespace frostwall::project {

// The number v holds (nlohmann::json or ordered_json); NaN for anything
// else.
template <class J>
double number_or_nan(const J& v) {
  return v.is_number() ? v.template get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// The number at object[key]; none when `object` is no object, lacks the
// key or holds no number there.
template <class J>
std::optional<double> number_at(const J& object, const char* key) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number()) return std::nullopt;
  return object[key].template get<double>();
}

}  // namespace frostwall::project
