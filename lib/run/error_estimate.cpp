#include "run/error_estimate.hpp"

#include <chrono>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <limits>

#include "io/atomic_file.hpp"
#include "io/csv_table.hpp"
#include "project/json_numbers.hpp"
#include "io/summary_file.hpp"
#include "run/error_law.hpp"

namespace frostwall::run {

namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;
using project::number_or_nan;
namespace keys = summary::keys;

namespace {

constexpr double missing = std::numeric_limits<double>::quiet_NaN();
constexpr const char* scratch_name = ".error_estimate";

ordered_json or_null(double e) { return std::isfinite(e) ? ordered_json(e) : ordered_json(nullptr); }

// The member at a path of keys, or null.
template <class J>
const J& at(const J& object, const std::vector<std::string>& path) {
  static const J none;
  const J* v = &object;
  for (const auto& key : path) {
    if (!v->is_object() || !v->contains(key)) return none;
    v = &(*v)[key];
  }
  return *v;
}

// Puts new_key right after key (the error beside its number).
void put_after(ordered_json& object, const std::string& key, const std::string& new_key, const ordered_json& value) {
  ordered_json rebuilt = ordered_json::object();
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (it.key() == new_key) continue;
    rebuilt[it.key()] = *it;
    if (it.key() == key) rebuilt[new_key] = value;
  }
  object = std::move(rebuilt);
}

struct Twins {
  std::vector<const json*> summaries;
  double ratio = 1.5;  // mean twin spacing over the run's
};

// The twins' mean spacing over the run's (run.spacing of each summary);
// the nominal 1.5 when a summary lacks it.
double twin_ratio(double h, const std::vector<json>& twins) {
  double ratio = 0.0;
  for (const auto& s : twins)
    ratio += number_or_nan(at(s, {keys::run, keys::spacing})) / h / static_cast<double>(twins.size());
  return std::isfinite(ratio) && ratio > 1.0 ? ratio : 1.5;
}

// A number of the summary (at path) and its error beside it.
void number_entry(ordered_json& summary, const Twins& twins, const std::vector<std::string>& path) {
  ordered_json* parent = &summary;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    if (!parent->is_object() || !parent->contains(path[i])) return;
    parent = &(*parent)[path[i]];
  }
  if (!parent->is_object() || !parent->contains(path.back())) return;
  std::vector<double> coarse;
  for (const auto* s : twins.summaries) coarse.push_back(number_or_nan(at(*s, path)));
  put_after(*parent, path.back(), keys::error_of(path.back()),
            or_null(number_error(number_or_nan((*parent)[path.back()]), coarse, twins.ratio)));
}

// A quantity of every wall entry (one per snapshot), as one series.
void wall_entry(ordered_json& wall, const std::vector<const json*>& twin_walls, double ratio,
                const std::vector<std::string>& path) {
  std::vector<double> fine;
  std::vector<std::vector<double>> coarse(twin_walls.size());
  for (const auto& w : wall) fine.push_back(number_or_nan(at(w, path)));
  for (std::size_t k = 0; k < twin_walls.size(); ++k)
    for (const auto& w : *twin_walls[k]) coarse[k].push_back(number_or_nan(at(w, path)));
  const auto errors = series_errors(fine, coarse, ratio);
  const std::vector<std::string> parent_path(path.begin(), path.end() - 1);
  for (std::size_t t = 0; t < wall.size(); ++t) {
    ordered_json* parent = &wall[t];
    for (const auto& key : parent_path) parent = parent && parent->contains(key) ? &(*parent)[key] : nullptr;
    if (parent && parent->is_object() && parent->contains(path.back()))
      put_after(*parent, path.back(), keys::error_of(path.back()), or_null(errors[t]));
  }
}

// Rows [time, value, ...] (a front, a sensor): rows [time, error, ...].
ordered_json row_errors(const ordered_json& rows, const std::vector<const json*>& twin_rows, double ratio) {
  ordered_json result = ordered_json::array();
  if (!rows.is_array() || rows.empty() || !rows[0].is_array()) return result;
  const std::size_t columns = rows[0].size();
  std::vector<std::vector<double>> errors(columns);
  for (std::size_t c = 1; c < columns; ++c) {
    std::vector<double> fine;
    std::vector<std::vector<double>> coarse(twin_rows.size());
    for (const auto& r : rows) fine.push_back(r.size() > c ? number_or_nan(r[c]) : missing);
    for (std::size_t k = 0; k < twin_rows.size(); ++k)
      if (twin_rows[k]->is_array())
        for (const auto& r : *twin_rows[k])
          coarse[k].push_back(r.is_array() && r.size() > c ? number_or_nan(r[c]) : missing);
    errors[c] = series_errors(fine, coarse, ratio);
  }
  for (std::size_t t = 0; t < rows.size(); ++t) {
    ordered_json row = ordered_json::array({rows[t][0]});
    for (std::size_t c = 1; c < columns; ++c) row.push_back(or_null(errors[c][t]));
    result.push_back(row);
  }
  return result;
}

// "monitoring" {name: rows} -> "monitoring_error" {name: rows of errors}.
void sensor_entries(ordered_json& summary, const Twins& twins, const std::string& key) {
  if (!summary.contains(key) || !summary[key].is_object()) return;
  ordered_json errors = ordered_json::object();
  for (auto it = summary[key].begin(); it != summary[key].end(); ++it) {
    std::vector<const json*> twin_rows;
    for (const auto* s : twins.summaries) twin_rows.push_back(&at(*s, {key, it.key()}));
    errors[it.key()] = row_errors(*it, twin_rows, twins.ratio);
  }
  put_after(summary, key, keys::error_of(key), errors);
}

// Under seepage: each gap's closure day, matched by the pipes it lies between.
void gap_entries(ordered_json& summary, const Twins& twins) {
  if (!summary.contains(keys::groundwater)) return;
  auto gap_error = [&](ordered_json& gap) {
    if (!gap.is_object() || !gap.contains(keys::closure_day)) return;
    std::vector<double> coarse;
    for (const auto* s : twins.summaries) {
      double c = missing;
      for (const auto& g : at(*s, {keys::groundwater, keys::gaps}))
        if (g.value("between", json()) == json(gap["between"])) c = number_or_nan(g.value(keys::closure_day, json()));
      coarse.push_back(c);
    }
    put_after(gap, keys::closure_day, keys::error_of(keys::closure_day),
              or_null(number_error(number_or_nan(gap[keys::closure_day]), coarse, twins.ratio)));
  };
  auto& g = summary[keys::groundwater];
  if (g.contains(keys::gaps))
    for (auto& gap : g[keys::gaps]) gap_error(gap);
  if (g.contains("last_gap")) gap_error(g["last_gap"]);
}

}  // namespace

void add_summary_errors(ordered_json& summary, const std::vector<json>& twin_summaries) {
  Twins twins;
  for (const auto& s : twin_summaries) twins.summaries.push_back(&s);
  twins.ratio = twin_ratio(number_or_nan(at(summary, {keys::run, keys::spacing})), twin_summaries);
  number_entry(summary, twins, {keys::closure_time_days});
  number_entry(summary, twins, {keys::front_contact_days});
  if (summary.contains(keys::wall) && summary[keys::wall].is_array()) {
    std::vector<const json*> twin_walls;
    for (const auto* s : twins.summaries) twin_walls.push_back(&at(*s, {keys::wall}));
    for (const auto& path : std::vector<std::vector<std::string>>{{keys::OA, keys::thickness},
                                                                  {keys::OB, keys::thickness},
                                                                  {keys::min_thickness},
                                                                  {keys::mean_temperature_OB},
                                                                  {keys::isotherm_thickness},
                                                                  {keys::isotherm_mean_temperature},
                                                                  {keys::utilisation},
                                                                  {keys::min_thickness_upstream},
                                                                  {keys::min_thickness_downstream}})
      wall_entry(summary[keys::wall], twin_walls, twins.ratio, path);
  }
  number_entry(summary, twins, {keys::design, keys::reached_day});
  number_entry(summary, twins, {keys::design, keys::met_day});
  gap_entries(summary, twins);
  if (summary.contains(keys::front) && summary[keys::front].is_array()) {
    std::vector<const json*> twin_rows;
    for (const auto* s : twins.summaries) twin_rows.push_back(&at(*s, {keys::front}));
    put_after(summary, keys::front, keys::error_of(keys::front),
              row_errors(summary[keys::front], twin_rows, twins.ratio));
  }
  sensor_entries(summary, twins, keys::monitoring);
  sensor_entries(summary, twins, keys::monitoring_solid);
}

namespace {

// A run's CSV table with a "<column>_error" column for every column but the
// first, from its twins' tables (same rows): the lines as written, extended.
void add_csv_errors(const fs::path& file, const std::vector<fs::path>& twin_files, double ratio) {
  if (!fs::exists(file)) return;
  const io::CsvTable fine = io::read_csv(file);
  std::vector<io::CsvTable> twins;
  for (const auto& f : twin_files) {
    if (!fs::exists(f)) return;
    twins.push_back(io::read_csv(f));
  }
  std::vector<std::vector<double>> errors(fine.header.size());
  for (std::size_t c = 1; c < fine.header.size(); ++c) {
    std::vector<std::vector<double>> coarse;
    for (const auto& t : twins)
      coarse.push_back(t.column(fine.header[c]) ? *t.column(fine.header[c]) : std::vector<double>());
    errors[c] = series_errors(fine.columns[c], coarse, ratio);
  }
  std::ifstream in(file);
  std::string line, text;
  std::getline(in, line);
  text = line;
  for (std::size_t c = 1; c < fine.header.size(); ++c) text += fmt::format(",{}_error", fine.header[c]);
  text += "\n";
  for (std::size_t row = 0; std::getline(in, line);) {
    if (line.empty()) continue;
    text += line;
    for (std::size_t c = 1; c < fine.header.size(); ++c)
      text += std::isfinite(errors[c][row]) ? fmt::format(",{:.3g}", errors[c][row]) : std::string(",");
    text += "\n";
    ++row;
  }
  io::write_text_file(file, text);
}

// The scratch directory of the twins, removed however the estimate ends.
struct Scratch {
  fs::path dir;
  ~Scratch() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  fs::path twin(std::size_t k) const { return dir / fmt::format("twin_{}", k + 1); }
};

}  // namespace

void add_error_estimate(const project::Project& p, const project::RunOptions& options, const EngineRun& engine,
                        summary::Summary& run) {
  const fs::path out = p.output.directory;
  const auto start = std::chrono::steady_clock::now();
  ordered_json doc = summary::to_json(run);
  const double h = run.run && run.run->spacing ? *run.run->spacing : missing;
  Scratch scratch{out / scratch_name};
  std::vector<json> twins;
  std::string unavailable;
  for (std::size_t k = 0; k < coarse_ratios.size() && unavailable.empty(); ++k) {
    project::Project twin = p;
    twin.numerics.spacing = coarse_ratios[k] * h;
    twin.numerics.error_estimate = false;
    twin.output.directory = scratch.twin(k).string();
    twin.output.vtk = twin.output.full_ring = twin.output.report = false;
    project::RunOptions quiet;
    quiet.progress = options.progress;
    if (options.note)
      options.note(fmt::format("error estimate: coarser run {} of {}, spacing {:.4g} m", k + 1, coarse_ratios.size(),
                               *twin.numerics.spacing));
    try {
      project::check_spacing(twin);
      twins.push_back(json(summary::to_json(engine(twin, quiet))));
    } catch (const project::ProjectError& e) {
      unavailable = fmt::format("the run at {:.4g} times the spacing cannot be made: {}", coarse_ratios[k],
                                e.problems().empty() ? std::string() : e.problems().front());
    } catch (const std::exception& e) {
      unavailable = fmt::format("the run at {:.4g} times the spacing failed: {}", coarse_ratios[k], e.what());
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!unavailable.empty()) {
    doc[keys::error_estimate] = {{keys::status, "unavailable"}, {"reason", unavailable}};
    doc[keys::warnings].push_back("no error estimate: " + unavailable);
    if (options.note) options.note("warning: no error estimate: " + unavailable);
  } else {
    add_summary_errors(doc, twins);
    std::vector<double> spacings, days;
    for (const auto& t : twins) {
      spacings.push_back(number_or_nan(at(t, {keys::run, keys::spacing})));
      days.push_back(number_or_nan(t.value(keys::closure_time_days, json())));
    }
    doc[keys::error_estimate] = {{keys::status, "done"},
                                 {"covers", "the discretisation only (spacing and the time steps that follow it)"},
                                 {"ratios", coarse_ratios},
                                 {"spacings", spacings},
                                 {"order", method_order},
                                 {"coarse_seconds", seconds},
                                 {"run_seconds", number_or_nan(at(doc, {keys::run, keys::wall_seconds}))}};
    if (doc.contains(keys::closure_time_days)) doc[keys::error_estimate][keys::coarse_closure_days] = days;
    for (const char* table : {"wall.csv", "monitoring.csv"}) {
      std::vector<fs::path> files;
      for (std::size_t k = 0; k < twins.size(); ++k) files.push_back(scratch.twin(k) / table);
      add_csv_errors(out / table, files, twin_ratio(h, twins));
    }
  }
  run = summary::from_json(doc);
  io::write_summary(out, run);
}

}  // namespace frostwall::run
