// Checks of a report's view against its template (tests only): whether a
// name is anywhere in the view, a template split at one section, and every
// name of a section in the view.
#pragma once

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>

#include "report/mustache_view.hpp"
#include "report/templates.hpp"

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

// Every name a section of the report's template uses is in the view.
inline void check_section_filled(const nlohmann::json& view, const std::string& section) {
  const auto block = split_section(report::templates::report_html, section).first;
  for (const auto& name : report::template_names(block)) {
    INFO(name);
    CHECK(has_key(view, name));
  }
}

}  // namespace frostwall::test
