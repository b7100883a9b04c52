// Reading a JSON document value by value while carrying each value's path,
// so that every problem can name where it is ("layout.rings[0].radius").
// Used by lib/project and by lib/study (study files are checked the same way).
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace frostwall::project::detail {

using Json = nlohmann::json;

// One value of the document, or the absence of one. The readers report what
// is wrong to a shared list and return nullopt rather than throwing, so a
// single pass finds every problem of a file.
class Node {
 public:
  Node(const Json* value, std::string path, std::vector<std::string>& problems)
      : value_(value), path_(std::move(path)), problems_(&problems) {}

  bool present() const { return value_ != nullptr; }
  const Json& json() const { return *value_; }  // only when present()
  const std::string& path() const { return path_; }
  void problem(const std::string& text) const { problems_->push_back(path_ + ": " + text); }

  // A child: absent when this is not an object or has no such key.
  Node operator[](std::string_view key) const;
  Node operator[](std::size_t index) const;

  // The same node, but the readers below report it when it is missing.
  Node required() const;
  // True when present; reports "required field is missing" if required.
  bool given() const;

  // An object whose keys are all in `fields`; each other key is reported as
  // an unknown field, so a typo cannot pass silently.
  bool object(std::initializer_list<std::string_view> fields) const;
  std::optional<std::size_t> array() const;  // its size
  std::optional<double> number() const;
  std::optional<double> positive() const;
  std::optional<double> non_negative() const;
  std::optional<int> count() const;  // a positive integer
  std::optional<bool> boolean() const;
  std::optional<std::string> string(bool may_be_empty = false) const;

  // A string naming one of `options`; reports "unknown <what> 'x' (expected ...)".
  template <class E>
  std::optional<E> choice(std::string_view what, std::initializer_list<std::pair<std::string_view, E>> options) const {
    const auto name = string(true);
    if (!name) return std::nullopt;
    std::string expected;
    for (const auto& [option, value] : options) {
      if (option == *name) return value;
      expected += (expected.empty() ? "" : ", ") + std::string(option);
    }
    problem("unknown " + std::string(what) + " '" + *name + "' (expected " + expected + ")");
    return std::nullopt;
  }

  std::string type() const { return value_->type_name(); }  // "number", "string", ...
  std::string shown() const { return value_->dump(); }      // the value as written

 private:
  const Json* value_;
  std::string path_;
  std::vector<std::string>* problems_;
  bool required_ = false;
};

}  // namespace frostwall::project::detail

namespace frostwall::project::detail {

// Parses a JSON text; nullopt after adding one problem line: the parser's
// own message (prefixed "<source>: not valid JSON: "), a number out of the
// range of a double named by its path, or each key given twice in one
// object named by its path (the parser would silently keep the last).
std::optional<Json> parse_document(const std::string& text, const std::string& source,
                                   std::vector<std::string>& problems);

}  // namespace frostwall::project::detail
