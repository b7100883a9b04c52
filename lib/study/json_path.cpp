#include "study/json_path.hpp"

#include <cctype>
#include <stdexcept>

namespace frostwall::study {

using nlohmann::json;

namespace {

std::string escape_token(const std::string& key) {
  std::string out;
  for (char c : key) out += c == '~' ? "~0" : (c == '/' ? "~1" : std::string(1, c));
  return out;
}

}  // namespace

std::optional<json::json_pointer> parse_path(const std::string& path, std::string& error) {
  if (path.empty()) {
    error = "must not be empty";
    return std::nullopt;
  }
  if (path.front() == '/') {
    try {
      return json::json_pointer(path);
    } catch (const json::exception&) {
      error = "not a valid JSON pointer: '" + path + "'";
      return std::nullopt;
    }
  }
  // Dotted: keys separated by '.', array indices as [n].
  std::string pointer;
  std::size_t i = 0;
  bool expect_key = true;
  while (i < path.size()) {
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      const std::string index = close == std::string::npos ? "" : path.substr(i + 1, close - i - 1);
      if (index.empty() || index.find_first_not_of("0123456789") != std::string::npos || expect_key) {
        error = "not a valid path: '" + path + "' (keys separated by '.', array elements as [0])";
        return std::nullopt;
      }
      pointer.append("/").append(index);
      i = close + 1;
      continue;
    }
    if (path[i] == '.') {
      if (expect_key) break;  // empty key
      expect_key = true;
      ++i;
      continue;
    }
    const std::size_t end = path.find_first_of(".[", i);
    const std::string key = path.substr(i, end == std::string::npos ? std::string::npos : end - i);
    pointer.append("/").append(escape_token(key));
    expect_key = false;
    i = end == std::string::npos ? path.size() : end;
  }
  if (expect_key) {
    error = "not a valid path: '" + path + "' (keys separated by '.', array elements as [0])";
    return std::nullopt;
  }
  return json::json_pointer(pointer);
}

void merge_at(json& document, const json::json_pointer& where, const json& patch) {
  if (where.empty()) {
    document.merge_patch(patch);
    return;
  }
  // Walk down, creating objects for missing keys.
  json* node = &document;
  std::string walked;
  // json_pointer has no public token list; rebuild it from the string form.
  std::vector<std::string> tokens;
  {
    const std::string s = where.to_string();
    std::size_t pos = 1;
    while (pos <= s.size()) {
      const std::size_t next = s.find('/', pos);
      std::string t = s.substr(pos, next == std::string::npos ? std::string::npos : next - pos);
      std::string unescaped;
      for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] == '~' && k + 1 < t.size()) unescaped += t[++k] == '0' ? '~' : '/';
        else unescaped += t[k];
      }
      tokens.push_back(unescaped);
      if (next == std::string::npos) break;
      pos = next + 1;
    }
  }
  for (std::size_t k = 0; k < tokens.size(); ++k) {
    const std::string& t = tokens[k];
    const bool last = k + 1 == tokens.size();
    if (node->is_null()) *node = json::object();
    if (node->is_object()) {
      if (last && patch.is_null()) {
        node->erase(t);
        return;
      }
      node = &(*node)[t];
    } else if (node->is_array()) {
      const bool digits = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
      if (!digits || std::stoul(t) >= node->size())
        throw std::invalid_argument(walked + "/" + t + ": no such element in the base project");
      if (last && patch.is_null()) {
        node->erase(std::stoul(t));
        return;
      }
      node = &(*node)[std::stoul(t)];
    } else {
      throw std::invalid_argument((walked.empty() ? "/" : walked) + " is a " + node->type_name() + ", not an object");
    }
    walked.append("/").append(t);
  }
  node->merge_patch(patch);
}

}  // namespace frostwall::study
