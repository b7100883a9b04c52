#include "report/view_numbers.hpp"

#include <cmath>
#include <limits>

#include "report/nice_scale.hpp"

namespace frostwall::report {

std::string number(double v, int decimals) { return std::isfinite(v) ? tick_label(v, decimals) : "–"; }

std::string number(const nlohmann::json& v, int decimals) {
  return v.is_number() ? number(v.get<double>(), decimals) : "–";
}

double get(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace frostwall::report
