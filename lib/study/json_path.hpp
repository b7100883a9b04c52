// Addressing a value of a project file from a study: a JSON pointer
// ("/pipe/temperature") or the dotted path the error messages use
// ("pipe.temperature", "layout.rings[0].radius"), and merging a value there.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace frostwall::study {

// nullopt, with `error` set, for a malformed path.
std::optional<nlohmann::json::json_pointer> parse_path(const std::string& path, std::string& error);

// RFC 7386 merge of `patch` into the value at `where` (objects merge key by
// key, anything else replaces, null removes). Missing objects on the way
// are created. Throws std::invalid_argument when the way runs through a
// value that is not an object (or an array index that does not exist).
void merge_at(nlohmann::json& document, const nlohmann::json::json_pointer& where, const nlohmann::json& patch);

}  // namespace frostwall::study
