// Numbers as the report's pages write them (report.html and study.html),
// and the numbers they look up in a run's summary.json.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace frostwall::report {

// "1.23" with `decimals` places and a true minus sign; "–" for NaN or
// infinity.
std::string number(double v, int decimals);
// The same for a JSON value; "–" for null or anything not a number.
std::string number(const nlohmann::json& v, int decimals);

// j[key] as a double; NaN when j has no such key or it holds no number.
double get(const nlohmann::json& j, const char* key);

}  // namespace frostwall::report
