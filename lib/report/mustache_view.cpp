#include "report/mustache_view.hpp"

#include <algorithm>
#include <fmt/core.h>
#include <kainjow/mustache.hpp>
#include <stdexcept>

namespace frostwall::report {

namespace {

namespace mustache = kainjow::mustache;

mustache::data to_data(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      mustache::data d{mustache::data::type::object};
      for (const auto& [key, value] : j.items()) d.set(key, to_data(value));
      return d;
    }
    case nlohmann::json::value_t::array: {
      mustache::data d{mustache::data::type::list};
      for (const auto& value : j) d.push_back(to_data(value));
      return d;
    }
    case nlohmann::json::value_t::string: return mustache::data{j.get<std::string>()};
    case nlohmann::json::value_t::boolean: return mustache::data{j.get<bool>()};
    case nlohmann::json::value_t::null: return mustache::data{false};
    default: return mustache::data{fmt::format("{:g}", j.get<double>())};
  }
}

}  // namespace

std::string render_template(std::string_view template_text, const nlohmann::json& view) {
  mustache::mustache tmpl{std::string(template_text)};
  if (!tmpl.is_valid()) throw std::runtime_error("report template: " + tmpl.error_message());
  std::string out = tmpl.render(to_data(view));
  if (!tmpl.error_message().empty()) throw std::runtime_error("report template: " + tmpl.error_message());
  return out;
}

std::vector<std::string> template_names(std::string_view t) {
  std::vector<std::string> names;
  std::size_t pos = 0;
  while ((pos = t.find("{{", pos)) != std::string_view::npos) {
    const bool triple = t.substr(pos, 3) == "{{{";
    const std::size_t start = pos + (triple ? 3 : 2);
    const std::size_t end = t.find(triple ? "}}}" : "}}", start);
    if (end == std::string_view::npos) break;
    std::string_view tag = t.substr(start, end - start);
    pos = end + 2;
    while (!tag.empty() && tag.front() == ' ') tag.remove_prefix(1);
    if (!tag.empty() && (tag.front() == '#' || tag.front() == '^' || tag.front() == '&')) tag.remove_prefix(1);
    else if (!tag.empty() && (tag.front() == '/' || tag.front() == '!' || tag.front() == '>' || tag.front() == '='))
      continue;
    while (!tag.empty() && (tag.front() == ' ')) tag.remove_prefix(1);
    while (!tag.empty() && (tag.back() == ' ')) tag.remove_suffix(1);
    if (tag.empty() || tag == ".") continue;
    const std::string name(tag);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace frostwall::report
