#include "project/json_reader.hpp"

#include <algorithm>
#include <limits>

namespace frostwall::project::detail {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// " (did you mean 'spacing'?)" for a near miss, else nothing.
std::string suggestion(std::string_view key, std::initializer_list<std::string_view> fields) {
  std::string_view best;
  std::size_t best_distance = 3;  // more than two edits is not a typo
  for (const auto field : fields) {
    const std::size_t d = edit_distance(key, field);
    if (d < best_distance && d < field.size()) best = field, best_distance = d;
  }
  return best.empty() ? "" : " (did you mean '" + std::string(best) + "'?)";
}

}  // namespace

Node Node::operator[](std::string_view key) const {
  const Json* child = nullptr;
  if (value_ && value_->is_object()) {
    const auto it = value_->find(std::string(key));
    if (it != value_->end()) child = &*it;
  }
  return {child, path_.empty() ? std::string(key) : path_ + "." + std::string(key), *problems_};
}

Node Node::operator[](std::size_t index) const {
  const Json* child = value_ && value_->is_array() && index < value_->size() ? &(*value_)[index] : nullptr;
  return {child, path_ + "[" + std::to_string(index) + "]", *problems_};
}

Node Node::required() const {
  Node n = *this;
  n.required_ = true;
  return n;
}

bool Node::given() const {
  if (!value_ && required_) problem("required field is missing");
  return value_ != nullptr;
}

bool Node::object(std::initializer_list<std::string_view> fields) const {
  if (!given()) return false;
  if (!value_->is_object()) {
    problem("must be an object, got " + type());
    return false;
  }
  for (const auto& [key, value] : value_->items())
    if (std::find(fields.begin(), fields.end(), key) == fields.end())
      (*this)[key].problem("unknown field" + suggestion(key, fields));
  return true;
}

std::optional<std::size_t> Node::array() const {
  if (!given()) return std::nullopt;
  if (!value_->is_array()) {
    problem("must be an array, got " + type());
    return std::nullopt;
  }
  return value_->size();
}

std::optional<double> Node::number() const {
  if (!given()) return std::nullopt;
  if (!value_->is_number()) {
    problem("must be a number, got " + type());
    return std::nullopt;
  }
  return value_->get<double>();
}

std::optional<double> Node::positive() const {
  const auto v = number();
  if (v && !(*v > 0)) {
    problem("must be positive, got " + shown());
    return std::nullopt;
  }
  return v;
}

std::optional<double> Node::non_negative() const {
  const auto v = number();
  if (v && *v < 0) {
    problem("must not be negative, got " + shown());
    return std::nullopt;
  }
  return v;
}

std::optional<int> Node::count() const {
  if (!given()) return std::nullopt;
  if (!value_->is_number() || !value_->is_number_integer() || value_->get<double>() < 1 ||
      value_->get<double>() > std::numeric_limits<int>::max()) {
    problem("must be a positive integer, got " + (value_->is_number() ? shown() : type()));
    return std::nullopt;
  }
  return value_->get<int>();
}

std::optional<bool> Node::boolean() const {
  if (!given()) return std::nullopt;
  if (!value_->is_boolean()) {
    problem("must be true or false, got " + type());
    return std::nullopt;
  }
  return value_->get<bool>();
}

std::optional<std::string> Node::string(bool may_be_empty) const {
  if (!given()) return std::nullopt;
  if (!value_->is_string()) {
    problem("must be a string, got " + type());
    return std::nullopt;
  }
  auto s = value_->get<std::string>();
  if (s.empty() && !may_be_empty) {
    problem("must not be empty");
    return std::nullopt;
  }
  return s;
}

}  // namespace frostwall::project::detail
