#include "study/study_report.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <map>

#include "io/atomic_file.hpp"
#include "report/mustache_view.hpp"
#include "report/nice_scale.hpp"
#include "report/run_files.hpp"
#include "report/svg_chart.hpp"
#include "report/view_numbers.hpp"
#include "report/templates.hpp"
#include "study/study_erosion.hpp"
#include "study/study_seepage.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace keys = summary::keys;

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Linear interpolation of column y at day x in wall.csv; NaN outside the run.
double at_day(const report::CsvTable& t, const char* column, double day) {
  const auto* d = t.column("day");
  const auto* y = t.column(column);
  if (!d || !y || d->empty()) return nan;
  // wall.csv starts at the first output interval: before it, nothing is frozen.
  if (day < d->front() || day > d->back() * (1 + 1e-9)) return nan;
  const auto it = std::lower_bound(d->begin(), d->end(), day);
  const std::size_t k = static_cast<std::size_t>(it - d->begin());
  if (k == 0 || (*d)[k] == day) return (*y)[k];
  const double a = (*y)[k - 1], b = (*y)[k], f = (day - (*d)[k - 1]) / ((*d)[k] - (*d)[k - 1]);
  if (!std::isfinite(a) || !std::isfinite(b)) return f < 0.5 ? a : b;
  return a + f * (b - a);
}

using report::number;
std::string csv_number(double v) { return std::isfinite(v) ? fmt::format("{:.6g}", v) : ""; }
std::string csv_text(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

}  // namespace

std::vector<Standing> rank_variants(const StudyRun& run, double thickness_day) {
  std::vector<Standing> s;
  for (const auto& v : run.variants) {
    Standing st;
    st.variant = &v;
    if (v.ok) {
      const auto& c = v.summary.value(keys::closure_time_days, json());
      if (c.is_number()) st.closure_day = c.get<double>();
      if (const auto& e = v.summary.value("closure_time_days_error", json()); e.is_number())
        st.closure_error = e.get<double>();
      if (fs::exists(v.directory / "wall.csv")) {
        const auto wall = report::read_csv(v.directory / "wall.csv");
        st.thickness = at_day(wall, "min_thickness_m", thickness_day);
        st.mean_temperature = at_day(wall, "mean_temperature_OB_C", thickness_day);
      }
    }
    s.push_back(st);
  }
  // Thickness ranking first (thicker is better), then the closure order.
  std::vector<Standing*> by_thickness;
  for (auto& st : s)
    if (st.variant->ok && std::isfinite(st.thickness)) by_thickness.push_back(&st);
  std::stable_sort(by_thickness.begin(), by_thickness.end(),
                   [](auto* a, auto* b) { return a->thickness > b->thickness; });
  for (std::size_t k = 0; k < by_thickness.size(); ++k) by_thickness[k]->thickness_rank = static_cast<int>(k + 1);
  auto key = [](const Standing& st) {
    // (group, value): closed by day, open by thickness (thicker first), failed last.
    if (!st.variant->ok) return std::pair{2, 0.0};
    if (st.closure_day) return std::pair{0, *st.closure_day};
    return std::pair{1, std::isfinite(st.thickness) ? -st.thickness : 0.0};
  };
  std::stable_sort(s.begin(), s.end(), [&](const Standing& a, const Standing& b) { return key(a) < key(b); });
  int position = 0;
  const Standing* before = nullptr;
  for (auto& st : s) {
    if (!st.variant->ok) continue;
    ++position;
    st.closure_tied = before && before->closure_day && st.closure_day &&
                      std::abs(*st.closure_day - *before->closure_day) < before->closure_error + st.closure_error;
    st.closure_rank = st.closure_tied ? before->closure_rank : position;
    before = &st;
  }
  return s;
}

void write_study_csv(const fs::path& file, const std::vector<Standing>& standings, double thickness_day) {
  std::string text =
      "closure_rank,variant,status,closure_day,closure_day_error,closure_tied,thickness_rank,thickness_day,min_thickness_m,mean_temperature_OB_C,"
      "design_pass,design_reached_day,particles,steps,wall_seconds,report,changes,error\n";
  for (const auto& st : standings) {
    const auto& v = *st.variant;
    const json design = v.ok ? v.summary.value(keys::design, json::object()) : json::object();
    const json facts = v.ok ? v.summary.value(keys::run, json::object()) : json::object();
    auto integer = [&](const char* key) {
      return facts.contains(key) ? fmt::format("{}", facts[key].get<long long>()) : std::string();
    };
    text += fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
        st.closure_rank ? std::to_string(st.closure_rank) : "", csv_text(v.name), v.ok ? "ok" : "failed",
        st.closure_day ? csv_number(*st.closure_day) : "", csv_number(st.closure_error),
        st.closure_tied ? "true" : "false", st.thickness_rank ? std::to_string(st.thickness_rank) : "",
        csv_number(thickness_day), csv_number(st.thickness), csv_number(st.mean_temperature),
        design.contains(keys::pass) ? (design[keys::pass].get<bool>() ? "true" : "false") : "",
        design.value(keys::reached_day, json()).is_number() ? csv_number(design[keys::reached_day].get<double>()) : "",
        integer(keys::particles), integer(keys::steps), csv_number(v.seconds),
        v.ok ? csv_text(v.name + "/report.html") : "", csv_text(v.changes),
        csv_text(v.errors.empty() ? "" : v.errors.front()));
  }
  io::write_text_file(file, text);
}

json study_view(const Study& study, const StudyRun& run, const std::vector<Standing>& standings) {
  json view;
  view["version"] = FROSTWALL_VERSION;
  view["css"] = std::string(report::templates::style_css);
  view["title"] = study.name;
  view["description"] = study.description.empty() ? json(false) : json(study.description);
  view["thickness_day"] = fmt::format("{:g}", study.thickness_day);
  std::size_t failed = 0;
  for (const auto& v : run.variants) failed += !v.ok;
  view["facts"] = json::array({
      {{"label", "base project"}, {"value", study.base.string()}},
      {{"label", "variants"},
       {"value",
        fmt::format("{} ({} finished, {} failed)", run.variants.size(), run.variants.size() - failed, failed)}},
      {{"label", "how they ran"},
       {"value", run.jobs > 1 ? fmt::format("{} at a time, {} OpenMP thread(s) each", run.jobs, run.threads)
                              : fmt::format("one after another, {} OpenMP thread(s) each", run.threads)}},
      {{"label", "wall time"}, {"value", fmt::format("{:.1f} s", run.seconds)}},
  });

  std::map<int, int> closure_ranks;  // how many variants share each closure rank
  for (const auto& st : standings) ++closure_ranks[st.closure_rank];
  auto row = [&](const Standing& st, int rank, bool closure_table) {
    const auto& v = *st.variant;
    const json design = v.summary.value(keys::design, json::object());
    const bool has_design = design.value(keys::required_thickness, json()).is_number() ||
                            design.value(keys::max_mean_temperature, json()).is_number();
    const bool pass = design.value(keys::pass, false);
    std::string closure = "not closed";
    if (st.closure_day)
      closure = std::isfinite(st.closure_error) ? report::with_error(*st.closure_day, st.closure_error, 1)
                                                : number(*st.closure_day, 1);
    const bool shared = closure_table && closure_ranks[rank] > 1;
    return json{{"rank", shared ? fmt::format("{}=", rank) : std::to_string(rank)},
                {"name", v.name},
                {"href", v.name + "/report.html"},
                {"closure", closure + (closure_table && shared ? " (tied)" : "")},
                {"thickness", number(st.thickness, 2)},
                {"mean_temperature", number(st.mean_temperature, 1)},
                {"design", !has_design ? "–"
                                       : (pass ? "pass, day " + number(design[keys::reached_day].is_number()
                                                                           ? design[keys::reached_day].get<double>()
                                                                           : nan,
                                                                       1)
                                               : "fail")},
                {"design_class", !has_design ? "" : (pass ? "pass" : "fail")},
                {"seconds", fmt::format("{:.1f}", v.seconds)},
                {"changes", v.changes}};
  };
  json by_closure = json::array(), by_thickness = json::array(), failures = json::array();
  for (const auto& st : standings)
    if (st.variant->ok) by_closure.push_back(row(st, st.closure_rank, true));
  std::vector<const Standing*> t;
  for (const auto& st : standings)
    if (st.thickness_rank > 0) t.push_back(&st);
  std::sort(t.begin(), t.end(), [](auto* a, auto* b) { return a->thickness_rank < b->thickness_rank; });
  for (const auto* st : t) by_thickness.push_back(row(*st, st->thickness_rank, false));
  for (const auto& st : standings)
    if (!st.variant->ok) {
      json lines = json::array();
      for (const auto& e : st.variant->errors) lines.push_back({{"line", e}});
      failures.push_back({{"name", st.variant->name}, {"changes", st.variant->changes}, {"errors", lines}});
    }
  view["by_closure"] = by_closure;
  view["by_thickness"] = by_thickness;
  view["failures"] = failures;
  view["has_failures"] = !failures.empty();
  view["has_results"] = !by_closure.empty();

  // The thinnest wall of every finished variant over time, overlaid.
  report::Chart chart;
  chart.title = "thinnest frozen wall over time, every variant";
  chart.x_label = "time (d)";
  chart.y_label = "thinnest wall (m)";
  chart.x_include = {0.0};
  chart.y_include = {0.0};
  chart.width = 900;
  chart.height = 380;
  std::optional<double> required;
  for (const auto& st : standings) {
    const auto& v = *st.variant;
    if (!v.ok || !fs::exists(v.directory / "wall.csv")) continue;
    const auto wall = report::read_csv(v.directory / "wall.csv");
    if (const auto* d = wall.column("day"); d && wall.column("min_thickness_m"))
      chart.series.push_back({v.name, *d, *wall.column("min_thickness_m"), "", false, false, 1.8});
    const auto& r = v.summary.value(keys::design, json::object()).value(keys::required_thickness, json());
    if (r.is_number() && !required) required = r.get<double>();
  }
  if (required) chart.guides.push_back({false, *required, fmt::format("required {} m", number(*required, 2))});
  chart.guides.push_back({true, study.thickness_day, fmt::format("ranking day {:g}", study.thickness_day)});
  view["chart_svg"] = chart.series.empty() ? "" : report::render_svg(chart);
  view["has_erosion"] = false;
  add_erosion(run, view);
  add_seepage(run, view);
  if (view["has_erosion"].get<bool>()) view["has_results"] = false;  // no frozen wall to rank
  return view;
}

void write_study_html(const fs::path& file, const Study& study, const StudyRun& run,
                      const std::vector<Standing>& standings) {
  io::write_text_file(file, report::render_template(report::templates::study_html, study_view(study, run, standings)));
}

}  // namespace frostwall::study

namespace frostwall::study {

StudyRun run_and_write_study(const Study& study, const StudyOptions& options) {
  std::filesystem::create_directories(study.output_directory);
  StudyRun run = run_study(study, options);
  if (!run.writer) return run;
  const auto standings = rank_variants(run, study.thickness_day);
  write_study_csv(study.output_directory / "study.csv", standings, study.thickness_day);
  write_study_html(study.output_directory / "study.html", study, run, standings);
  if (has_erosion(run)) write_erosion_csv(study.output_directory / "erosion.csv", run);
  return run;
}

}  // namespace frostwall::study
