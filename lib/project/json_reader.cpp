#include "project/json_reader.hpp"

#include <algorithm>
#include <limits>
#include <set>

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

// Walks the text as the parser reads it (nlohmann's SAX interface), keeping
// the path of the value being read, to name a key given twice or a number
// out of range.
class PathWalker {
 public:
  PathWalker(std::string source, std::vector<std::string>& problems)
      : source_(std::move(source)), problems_(&problems) {}
  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(Json::number_integer_t) { return value(); }
  bool number_unsigned(Json::number_unsigned_t) { return value(); }
  bool number_float(Json::number_float_t, const std::string&) { return value(); }
  bool string(std::string&) { return value(); }
  bool binary(Json::binary_t&) { return value(); }
  bool start_object(std::size_t) { return frames_.push_back(Frame{true, {}, 0, {}}), true; }
  bool start_array(std::size_t) { return frames_.push_back(Frame{false, {}, 0, {}}), true; }
  bool end_object() { return frames_.pop_back(), value(); }
  bool end_array() { return frames_.pop_back(), value(); }
  bool key(std::string& k) {
    Frame& f = frames_.back();
    f.key = k;
    if (!f.keys.insert(k).second)
      problems_->push_back(path() + ": given twice in one object (only one value may stand)");
    return true;
  }
  bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) {
    std::string message = e.what();
    if (e.id == 406) {  // out_of_range: a number beyond a double
      const std::string where = path();
      problems_->push_back((where.empty() ? source_ : where) + ": the number " + token +
                           " is out of range (beyond about 1.8e308)");
      return false;
    }
    // Drop the library's "[json.exception.parse_error.101] " tag; keep line and column.
    if (const auto tag_end = message.find("] "); message.starts_with("[json.exception") && tag_end != std::string::npos)
      message.erase(0, tag_end + 2);
    problems_->push_back(source_ + ": not valid JSON: " + message);
    return false;
  }

 private:
  struct Frame {
    bool object = true;
    std::string key;        // the key being read (objects)
    std::size_t index = 0;  // the element being read (arrays)
    std::set<std::string> keys;
  };
  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }
  // The path of the value being read, as Node names it: "a.b[2].c".
  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      if (!f.object) {
        p += '[';
        p += std::to_string(f.index);
        p += ']';
      } else {
        if (!p.empty()) p += '.';
        p += f.key;
      }
    }
    return p;
  }
  std::string source_;
  std::vector<std::string>* problems_;
  std::vector<Frame> frames_;
};

}  // namespace

std::optional<Json> parse_document(const std::string& text, const std::string& source,
                                   std::vector<std::string>& problems) {
  const std::size_t before = problems.size();
  PathWalker walker(source, problems);
  Json::sax_parse(text, &walker);
  if (problems.size() > before) return std::nullopt;
  try {
    return Json::parse(text);
  } catch (const Json::exception& e) {  // the walk above found what the parser would
    problems.push_back(source + ": not valid JSON: " + e.what());
    return std::nullopt;
  }
}

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
