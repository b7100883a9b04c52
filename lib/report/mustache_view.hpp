// Rendering a template of templates/ with a view built as JSON: the view is
// plain data (strings, booleans, lists, objects) that a test can inspect,
// converted to kainjow::mustache data at the last moment.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace frostwall::report {

// Throws std::runtime_error when the template does not parse. Numbers in
// the view are written with {:g}; null and false render as false sections.
std::string render_template(std::string_view template_text, const nlohmann::json& view);

// The names the template refers to ({{name}}, {{{name}}}, {{#name}},
// {{^name}}, {{&name}}), without duplicates, in order of first use.
std::vector<std::string> template_names(std::string_view template_text);

}  // namespace frostwall::report
