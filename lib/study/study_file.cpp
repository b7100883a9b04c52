#include "study/study_file.hpp"

#include <cerrno>
#include <cstring>
#include <fmt/core.h>
#include <fstream>
#include <map>
#include <sstream>

#include "project/json_reader.hpp"
#include "project/units.hpp"
#include "study/json_path.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;
using nlohmann::json;
using project::detail::Node;

namespace {

constexpr std::size_t max_variants = 1000;  // a typo in a product list should not start a week of runs

std::optional<std::string> read_file(const fs::path& path, std::string& error) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    error = "is a directory";
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = std::strerror(errno);
    return std::nullopt;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A value as a name part: strings as they are, numbers and booleans as written.
std::optional<std::string> default_label(const json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number() || v.is_boolean()) return v.dump();
  return std::nullopt;
}

struct Override {
  std::string name, changes;
  json patch;
};

struct Parameter {
  std::string path_text;  // as written, for messages and descriptions
  std::string node_path;  // "product[1]"
  json::json_pointer path;
  std::vector<json> values;
  std::vector<std::string> labels;
};

std::vector<Override> read_overrides(const Node& n) {
  std::vector<Override> out;
  const auto size = n.array();
  if (!size) return out;
  if (*size == 0) n.problem("must list at least one variant (or leave \"variants\" out)");
  for (std::size_t i = 0; i < *size; ++i) {
    const Node v = n[i];
    if (!v.object({"name", "patch", "description"})) continue;
    Override o;
    const auto name = v["name"].required().string();
    if (name && !valid_variant_name(*name))
      v["name"].problem("'" + *name +
                        "' cannot name a folder (use letters, digits and . _ - + =, not starting with '.')");
    o.name = name.value_or("");
    const Node patch = v["patch"].required();
    if (patch.given() && !patch.json().is_object())
      patch.problem("must be an object (a JSON merge patch of the project), got " + patch.type());
    else if (patch.given()) o.patch = patch.json();
    const auto description = v["description"].string();
    o.changes = description ? *description : (o.patch.is_object() ? o.patch.dump() : "");
    out.push_back(std::move(o));
  }
  return out;
}

std::vector<Parameter> read_product(const Node& n) {
  std::vector<Parameter> out;
  const auto size = n.array();
  if (!size) return out;
  if (*size == 0) n.problem("must list at least one parameter (or leave \"product\" out)");
  for (std::size_t i = 0; i < *size; ++i) {
    const Node p = n[i];
    if (!p.object({"path", "values", "labels"})) continue;
    Parameter q;
    q.node_path = p.path();
    bool ok = true;
    if (const auto path = p["path"].required().string()) {
      std::string error;
      if (const auto pointer = parse_path(*path, error)) q.path = *pointer, q.path_text = *path;
      else p["path"].problem(error), ok = false;
    } else {
      ok = false;
    }
    const Node values = p["values"].required();
    if (const auto count = values.array()) {
      if (*count == 0) values.problem("must list at least one value"), ok = false;
      for (std::size_t k = 0; k < *count; ++k) q.values.push_back(values.json()[k]);
    } else {
      ok = false;
    }
    const Node labels = p["labels"];
    if (labels.given()) {
      if (const auto count = labels.array()) {
        if (*count != q.values.size())
          labels.problem(fmt::format("must have one label per value ({}), got {}", q.values.size(), *count)),
              ok = false;
        for (std::size_t k = 0; k < *count; ++k)
          if (const auto label = labels[k].string()) {
            if (!valid_variant_name(*label))
              labels[k].problem("'" + *label + "' cannot be part of a folder name (use letters, digits and . _ - + =)"),
                  ok = false;
            q.labels.push_back(*label);
          } else {
            ok = false;
          }
      } else {
        ok = false;
      }
    } else {
      for (std::size_t k = 0; k < q.values.size(); ++k) {
        const auto label = default_label(q.values[k]);
        if (!label) {
          values[k].problem("an object or array value needs a name: give \"labels\" for this parameter");
          ok = false;
          continue;
        }
        if (!valid_variant_name(*label)) {
          values[k].problem("'" + *label + "' cannot be part of a folder name: give \"labels\" for this parameter");
          ok = false;
        }
        q.labels.push_back(*label);
      }
    }
    if (ok) out.push_back(std::move(q));
  }
  return out;
}

}  // namespace

bool variant_name_character(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-' || c == '+' || c == '=';
}

bool valid_variant_name(const std::string& name) {
  if (name.empty() || name.front() == '.' || name.size() > 120) return false;
  for (char c : name)
    if (!variant_name_character(c)) return false;
  return true;
}

namespace {

// The base project as JSON (study.base: its path, relative to the study
// file's directory); null when it cannot be read (a problem is reported).
json read_base(const Node& base_node, const fs::path& directory, Study& study) {
  json base;
  if (const auto base_file = base_node.string()) {
    study.base = fs::path(*base_file).is_absolute() ? fs::path(*base_file) : directory / *base_file;
    std::string error;
    if (const auto base_text = read_file(study.base, error)) {
      try {
        base = json::parse(*base_text);
        if (!base.is_object())
          base_node.problem("the base project " + study.base.string() + " is not a JSON object"), base = json();
      } catch (const json::exception&) {
        base_node.problem("the base project " + study.base.string() + " is not valid JSON");
      }
    } else {
      base_node.problem("cannot read " + study.base.string() + ": " + error);
    }
  }
  return base;
}

// The base project's last snapshot, in days (the default ranking day).
std::optional<double> last_snapshot_day(const json& base) {
  if (!(base.contains("time") && base["time"].is_object() && base["time"].contains("snapshots") &&
        base["time"]["snapshots"].is_array() && !base["time"]["snapshots"].empty() &&
        base["time"]["snapshots"].back().is_number()))
    return std::nullopt;
  const std::string unit = base["time"].value("unit", "d");
  const double factor = unit == "s" ? 1.0 / project::seconds_per_day : (unit == "h" ? 1.0 / 24 : 1.0);
  return base["time"]["snapshots"].back().get<double>() * factor;
}

}  // namespace

Study parse_study(const std::string& text, const fs::path& directory, const std::string& source) {
  std::vector<std::string> parse_problems;
  const auto parsed = project::detail::parse_document(text, source, parse_problems);
  if (!parsed) throw StudyError(parse_problems);
  const json& document = *parsed;
  if (!document.is_object())
    throw StudyError({source + ": must be a JSON object, got " + std::string(document.type_name())});

  std::vector<std::string> problems;
  const Node root(&document, "", problems);
  root.object({"name", "description", "base", "output", "patch", "variants", "product", "rank"});
  Study study;
  study.name = root["name"].required().string().value_or("");
  study.description = root["description"].string(true).value_or("");

  // The base project, as JSON; the study's own patch on top.
  json base = read_base(root["base"].required(), directory, study);
  const Node output = root["output"].required();
  if (output.object({"directory"}))
    if (const auto dir = output["directory"].required().string()) study.output_directory = *dir;
  const Node study_patch = root["patch"];
  if (study_patch.given() && !study_patch.json().is_object())
    study_patch.problem("must be an object (a JSON merge patch of the base project), got " + study_patch.type());
  else if (study_patch.given() && base.is_object()) base.merge_patch(study_patch.json());

  const Node rank = root["rank"];
  std::optional<double> thickness_day;
  if (rank.object({"thickness_day"})) thickness_day = rank["thickness_day"].positive();

  const Node variants_node = root["variants"], product_node = root["product"];
  std::vector<Override> overrides = read_overrides(variants_node);
  const std::vector<Parameter> product = read_product(product_node);
  if (!variants_node.present() && !product_node.present())
    problems.push_back(source +
                       ": a study needs \"variants\" (named merge patches), \"product\" (parameter lists), or both");
  if (!problems.empty() || !base.is_object()) {
    if (problems.empty()) problems.push_back("base: the base project could not be read");
    throw StudyError(std::move(problems));
  }

  // Default ranking day: the base's last snapshot (days).
  if (thickness_day) study.thickness_day = *thickness_day;
  else if (const auto day = last_snapshot_day(base)) study.thickness_day = *day;

  // Expand: every override (or the base alone) times every combination.
  if (overrides.empty()) overrides.push_back({"", "", json::object()});
  std::size_t combinations = 1;
  for (const auto& p : product) combinations *= p.values.size();
  if (overrides.size() * combinations > max_variants)
    throw StudyError(
        {fmt::format("product: {} variants; a study runs at most {}", overrides.size() * combinations, max_variants)});
  const std::string base_name = base.value("name", std::string("project"));
  std::map<std::string, std::string> seen;  // name -> where it came from
  for (std::size_t o = 0; o < overrides.size(); ++o) {
    for (std::size_t c = 0; c < combinations; ++c) {
      Variant v;
      v.project = base;
      v.project.merge_patch(overrides[o].patch);
      std::vector<std::string> name_parts, changes;
      if (!overrides[o].name.empty()) name_parts.push_back(overrides[o].name);
      if (!overrides[o].changes.empty()) changes.push_back(overrides[o].changes);
      std::size_t rest = c;
      std::vector<std::size_t> pick(product.size());
      for (std::size_t k = product.size(); k-- > 0;)
        pick[k] = rest % product[k].values.size(), rest /= product[k].values.size();
      for (std::size_t k = 0; k < product.size(); ++k) {
        const auto& p = product[k];
        try {
          merge_at(v.project, p.path, p.values[pick[k]]);
        } catch (const std::invalid_argument& e) {
          problems.push_back(p.node_path + ".path: cannot set '" + p.path_text + "' in the base project: " + e.what());
        }
        name_parts.push_back(p.labels[pick[k]]);
        changes.push_back(p.path_text + " = " + p.values[pick[k]].dump());
      }
      for (const auto& part : name_parts) v.name += (v.name.empty() ? "" : "+") + part;
      for (const auto& part : changes) v.changes += (v.changes.empty() ? "" : "; ") + part;
      if (v.changes.empty()) v.changes = "the base project";
      const std::string where = overrides[o].name.empty() ? "product" : fmt::format("variants[{}]", o);
      if (const auto it = seen.find(v.name); it != seen.end()) {
        problems.push_back(where + ": duplicate variant name '" + v.name + "' (also " + it->second + ")");
        continue;
      }
      seen[v.name] = where;
      // Each variant writes its own folder and report, named after it.
      if (!v.project.is_object()) v.project = json::object();
      if (v.project.value("name", json()) == json(base_name)) v.project["name"] = base_name + " (" + v.name + ")";
      json& output_settings = v.project["output"];
      if (!output_settings.is_object()) output_settings = json::object();
      output_settings["directory"] = (study.output_directory / v.name).string();
      output_settings["report"] = true;
      study.variants.push_back(std::move(v));
    }
  }
  if (!problems.empty()) throw StudyError(std::move(problems));
  return study;
}

Study load_study(const std::string& path) {
  std::string error;
  const auto text = read_file(path, error);
  if (!text) throw StudyError({path + ": cannot read: " + error});
  return parse_study(*text, fs::path(path).parent_path(), path);
}

}  // namespace frostwall::study
