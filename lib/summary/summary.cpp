#include "summary/summary.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace frostwall::summary {

using nlohmann::ordered_json;

namespace {

// Reading: a typed member's value taken out of `detail`, a null slot left
// in its place (nothing where the key is absent).
template <class T>
std::optional<T> take(ordered_json& detail, const char* key) {
  const auto it = detail.find(key);
  if (it == detail.end() || it->is_null()) return std::nullopt;
  T value = it->template get<T>();
  *it = nullptr;
  return value;
}

// Writing: the value into its slot (appended without one); null in a slot
// when unset.
template <class T>
void put(ordered_json& j, const char* key, const std::optional<T>& value) {
  if (value) j[key] = *value;
  else if (j.contains(key)) j[key] = nullptr;
}

// An object read as a typed member (its own slots inside).
template <class T, class Read>
std::optional<T> take_object(ordered_json& detail, const char* key, Read read) {
  const auto it = detail.find(key);
  if (it == detail.end() || !it->is_object()) return std::nullopt;
  T value = read(*it);
  *it = nullptr;
  return value;
}

// A typed member of S: its key and where it lives.
template <class S, class M>
struct Field {
  const char* key;
  std::optional<M> S::*member;
};

template <class S, class M>
constexpr Field<S, M> field(const char* key, std::optional<M> S::*member) {
  return {key, member};
}

// A field's value taken out of `detail`.
template <class S, class M>
std::optional<M> take_as(ordered_json& detail, const Field<S, M>& f) {
  return take<M>(detail, f.key);
}

// Each typed structure's members, by key.
constexpr auto stretch_fields = std::tuple{field(keys::inner, &Stretch::inner), field(keys::outer, &Stretch::outer),
                                           field(keys::thickness, &Stretch::thickness)};
constexpr auto wall_fields = std::tuple{field(keys::day, &WallEntry::day),
                                        field(keys::min_thickness, &WallEntry::min_thickness),
                                        field(keys::thinnest_angle_deg, &WallEntry::thinnest_angle_deg),
                                        field(keys::mean_temperature_OB, &WallEntry::mean_temperature_OB)};
constexpr auto design_fields = std::tuple{field(keys::required_thickness, &Design::required_thickness),
                                          field(keys::max_mean_temperature, &Design::max_mean_temperature),
                                          field(keys::reached_day, &Design::reached_day),
                                          field(keys::met_day, &Design::met_day), field(keys::pass, &Design::pass)};
constexpr auto run_fields = std::tuple{
    field(keys::particles, &RunInfo::particles),       field(keys::steps, &RunInfo::steps),
    field(keys::wall_seconds, &RunInfo::wall_seconds), field(keys::integrator, &RunInfo::integrator),
    field(keys::spacing, &RunInfo::spacing),           field(keys::smoothing_length, &RunInfo::smoothing_length)};

// An object read into S (its fields taken out of its detail) and back.
template <class S, class Fields>
S read_fields(const ordered_json& j, const Fields& fields) {
  S s;
  s.detail = j;
  std::apply([&](const auto&... f) { ((s.*f.member = take_as(s.detail, f)), ...); }, fields);
  return s;
}

template <class S, class Fields>
ordered_json write_fields(const S& s, const Fields& fields) {
  ordered_json j = s.detail;
  std::apply([&](const auto&... f) { (put(j, f.key, s.*f.member), ...); }, fields);
  return j;
}

Stretch stretch_of(const ordered_json& j) { return read_fields<Stretch>(j, stretch_fields); }
Design design_of(const ordered_json& j) { return read_fields<Design>(j, design_fields); }
RunInfo run_of(const ordered_json& j) { return read_fields<RunInfo>(j, run_fields); }

WallEntry wall_entry_of(const ordered_json& j) {
  WallEntry w = read_fields<WallEntry>(j, wall_fields);
  w.OA = take_object<Stretch>(w.detail, keys::OA, stretch_of);
  w.OB = take_object<Stretch>(w.detail, keys::OB, stretch_of);
  return w;
}

ordered_json json_of(const WallEntry& w) {
  ordered_json j = write_fields(w, wall_fields);
  if (w.OA) j[keys::OA] = write_fields(*w.OA, stretch_fields);
  if (w.OB) j[keys::OB] = write_fields(*w.OB, stretch_fields);
  return j;
}

// A typed list's slot is an empty array (a null there is kept as written).
template <class T>
std::vector<T> take_list(ordered_json& detail, const char* key, T (*read)(const ordered_json&)) {
  std::vector<T> list;
  const auto it = detail.find(key);
  if (it == detail.end() || !it->is_array()) return list;
  for (const auto& item : *it) list.push_back(read(item));
  *it = ordered_json::array();
  return list;
}

bool has_list(const ordered_json& j, const char* key) { return j.contains(key) && j.at(key).is_array(); }

std::string text_of(const ordered_json& j) { return j.get<std::string>(); }

// Non-finite numbers as the file holds them: null.
void null_non_finite(ordered_json& j) {
  if (j.is_number_float() && !std::isfinite(j.get<double>())) j = nullptr;
  else if (j.is_structured())
    for (auto& v : j) null_non_finite(v);
}

}  // namespace

const ordered_json& Summary::block(const char* key) const {
  static const ordered_json none;
  const auto it = detail.find(key);
  return it == detail.end() ? none : *it;
}

Summary from_json(const ordered_json& j) {
  if (!j.is_object()) throw std::invalid_argument("summary.json: an object expected");
  Summary s;
  s.detail = j;
  null_non_finite(s.detail);
  s.project = take<std::string>(s.detail, keys::project).value_or("");
  s.frostwall_version = take<std::string>(s.detail, keys::frostwall_version).value_or("");
  s.closure_time_days = take<double>(s.detail, keys::closure_time_days);
  s.front_contact_days = take<double>(s.detail, keys::front_contact_days);
  s.wall = take_list(s.detail, keys::wall, wall_entry_of);
  s.design = take_object<Design>(s.detail, keys::design, design_of);
  s.run = take_object<RunInfo>(s.detail, keys::run, run_of);
  s.warnings = take_list(s.detail, keys::warnings, text_of);
  return s;
}

ordered_json to_json(const Summary& s) {
  ordered_json j = s.detail;
  auto text = [&](const char* key, const std::string& value) {
    if (!value.empty() || j.contains(key)) j[key] = value;
  };
  text(keys::project, s.project);
  text(keys::frostwall_version, s.frostwall_version);
  put(j, keys::closure_time_days, s.closure_time_days);
  put(j, keys::front_contact_days, s.front_contact_days);
  if (!s.wall.empty() || has_list(j, keys::wall)) {
    ordered_json wall = ordered_json::array();
    for (const auto& w : s.wall) wall.push_back(json_of(w));
    j[keys::wall] = wall;
  }
  if (s.design) j[keys::design] = write_fields(*s.design, design_fields);
  if (s.run) j[keys::run] = write_fields(*s.run, run_fields);
  if (!s.warnings.empty() || has_list(j, keys::warnings)) j[keys::warnings] = s.warnings;
  return j;
}

const WallEntry* wall_at(const Summary& s, double day) {
  for (const auto& w : s.wall)
    if (w.day && std::abs(*w.day - day) <= 1e-9 * std::max(1.0, day)) return &w;
  return nullptr;
}

}  // namespace frostwall::summary
