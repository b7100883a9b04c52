// Checks of a report's view against its template (tests only): whether a
// name is anywhere in the view, and a template split at one section.
#pragma once

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

namespace frostwall::test {

inline bool has_key(const nlohmann::json& j, const std::string& key) {
  if (j.is_object()) {
    if (j.contains(key)) return true;
    for (const auto& [k, v] : j.items())
      if (has_key(v, key)) return true;
  } else if (j.is_array()) {
    for (const auto& v : j)
      if (has_key(v, key)) return true;
  }
  return false;
}

inline std::pair<std::string, std::string> split_section(std::string_view t, const std::string& name) {
  const std::string open = "{{#" + name + "}}", close = "{{/" + name + "}}";
  const std::size_t a = t.find(open), b = t.find(close);
  REQUIRE(a != std::string_view::npos);
  REQUIRE(b != std::string_view::npos);
  return {std::string(t.substr(a, b + close.size() - a)),
          std::string(t.substr(0, a)) + std::string(t.substr(b + close.size()))};
}

}  // namespace frostwall::test
