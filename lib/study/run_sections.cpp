#include "study/run_sections.hpp"
#include "study/excavation_overview.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <limits>
#include <optional>

#include "geometry/as_built.hpp"
#include "io/output_directory.hpp"
#include "io/paraview_script.hpp"
#include "io/shaft_vtm.hpp"
#include "run/check_project.hpp"
#include "study/ranks.hpp"
#include "study/run_coupled.hpp"
#include "summary/summary.hpp"

namespace frostwall::study {

namespace fs = std::filesystem;
using nlohmann::json;
namespace keys = summary::keys;

namespace {

// The survey desurveyed, checked, and the depths to run.
struct AsBuilt {
  std::vector<geometry::Pipe2> design;
  std::vector<geometry::PipeTrace> traces;
  std::vector<double> depths;
};

AsBuilt as_built(const project::Project& p) {
  const auto& section = std::get<project::ShaftSection>(p.geometry);
  AsBuilt a;
  a.design = geometry::all_pipe_positions(section.layout);
  a.traces = geometry::pipe_traces(*p.survey, a.design);
  if (auto problems = geometry::as_built_problems(p, a.traces, a.design); !problems.empty())
    throw project::ProjectError(std::move(problems));
  a.depths = geometry::section_depths(p, a.traces, a.design);
  return a;
}

std::string section_folder(double depth, bool intact) {
  return fmt::format("depth_{:06.2f}m{}", depth, intact ? "_intact" : "");
}

std::string section_name(double depth) { return fmt::format("{:g} m", std::round(depth * 100) / 100); }

// The layer whose depth range holds `depth` (-1 without layers).
int layer_at(const project::Project& p, const AsBuilt& a, double depth) {
  double deepest = 0.0;
  for (const auto& t : a.traces) deepest = std::max(deepest, t.bottom);
  for (const auto& r : geometry::layer_ranges(p, deepest))
    if (depth >= r.top && depth <= r.bottom) return r.layer;
  return p.layers.empty() ? -1 : 0;
}

// The section's project file: the base with the layer's patch, the pipes
// at their as-built positions at the depth as a measured layout.
json section_document(const project::Project& p, const json& base, const AsBuilt& a, double depth, bool intact) {
  json doc = base;
  for (const char* key : {"survey", "sections", "layers", "compare_intact", "failed_pipes"}) doc.erase(key);
  if (const int layer = layer_at(p, a, depth); layer >= 0) doc.merge_patch(json::parse(p.layers[layer].patch));
  if (doc.contains("design") && doc["design"].contains("pressure")) doc["design"]["depth"] = depth;
  std::optional<double> day;  // the day given for this listed depth
  if (p.excavation && !p.excavation->days.empty())
    for (std::size_t k = 0; k < p.sections.depths.size(); ++k)
      if (p.sections.depths[k] == depth) day = p.excavation->days[k];
  sink_at(doc, depth, day);
  json pipes = json::array(), failed = json::array();
  const auto here = geometry::pipes_at(a.traces, a.design, depth);
  for (std::size_t k = 0; k < here.size(); ++k) {
    pipes.push_back({{"x", here[k].x}, {"y", here[k].y}});
    if (here[k].failed && !intact) failed.push_back(k + 1);
  }
  doc["layout"] = {{"pattern", "pipes"}, {"pipes", pipes}};
  if (!failed.empty()) doc["failed_pipes"] = failed;
  doc["name"] = fmt::format("{}: section at {}{}", p.name, section_name(depth), intact ? " (intact)" : "");
  doc["output"]["directory"] = (fs::path(p.output.directory) / section_folder(depth, intact)).string();
  return doc;
}

json or_null(const json& v) { return v.is_number() ? v : json(nullptr); }

}  // namespace

// How far the wall at the last snapshot is from the design, as a share of
// each requirement, the smallest of: 1 - utilisation (strength check), the
// thinnest wall over the required thickness minus 1, and the mean
// temperature's distance below its limit over the limit's size. Below 0
// the design is not met. Null without a target.
json design_margin(const json& summary) {
  const json wall = summary.value(keys::wall, json::array());
  if (wall.empty()) return nullptr;
  const json& last = wall.back();
  const json design = summary.value(keys::design, json::object());
  std::optional<double> margin;
  auto take = [&](double m) { margin = margin ? std::min(*margin, m) : m; };
  if (last.value(keys::utilisation, json()).is_number()) take(1.0 - last[keys::utilisation].get<double>());
  const json required = design.value(keys::required_thickness, json());
  if (required.is_number() && required.get<double>() > 0)
    take(last.value(keys::min_thickness, 0.0) / required.get<double>() - 1.0);
  const json limit = design.value(keys::max_mean_temperature, json());
  if (limit.is_number()) {
    const json mean = last.value(keys::mean_temperature_OB, json());
    const double scale = std::max(std::abs(limit.get<double>()), 1.0);
    take(mean.is_number() ? (limit.get<double>() - mean.get<double>()) / scale : -1.0);
  }
  return margin ? json(*margin) : json(nullptr);
}

json wall_digest(const json& summary) {
  const json wall = summary.value(keys::wall, json::array());
  const json last = wall.empty() ? json::object() : wall.back();
  return {{keys::closure_time_days, or_null(summary.value(keys::closure_time_days, json()))},
          {keys::thinnest_wall, or_null(last.value(keys::min_thickness, json()))},
          {keys::thinnest_angle_deg, or_null(last.value(keys::thinnest_angle_deg, json()))},
          {keys::design_margin, design_margin(summary)},
          {keys::day, or_null(last.value(keys::day, json()))}};
}

namespace {

// A section's entry of the as-built summary.
json section_entry(const SectionRun& s, const json& summary, const std::vector<geometry::Pipe2>& pipes, double diameter,
                   const std::string& layer) {
  json gaps = json::array();
  double widest = 0.0;
  for (const auto& g : geometry::largest_gaps(pipes, diameter)) {
    gaps.push_back({{"ring", g.ring}, {"gap", g.gap}, {"between", {g.from, g.to}}, {"middle", {g.x, g.y}}});
    widest = std::max(widest, g.gap);
  }
  json listed = json::array();
  for (const auto& q : pipes) listed.push_back({q.number, q.x, q.y, q.failed});
  json entry = wall_digest(summary);
  entry.update({{"depth", s.depth},
                {"directory", s.folder},
                {"layer", layer.empty() ? json(nullptr) : json(layer)},
                {"largest_gap", widest},
                {"largest_gaps", gaps},
                {"pipes", listed}});
  return entry;
}

// The last snapshot's particle file of a section's folder: the whole ring
// when the run wrote one, else the simulated region.
std::optional<fs::path> last_field_file(const fs::path& dir) {
  for (const char* prefix : {"ring_", "field_"}) {
    std::vector<fs::path> files;
    if (fs::is_directory(dir))
      for (const auto& e : fs::directory_iterator(dir)) {
        const auto name = e.path().filename().string();
        if (name.rfind(prefix, 0) == 0 && e.path().extension() == ".vtu") files.push_back(e.path());
      }
    if (!files.empty()) return *std::max_element(files.begin(), files.end());
  }
  return std::nullopt;
}

// Every section's project file, checked, from the desurveyed shaft.
std::vector<SectionRun> section_runs(const project::Project& p, const std::string& project_text, const AsBuilt& a) {
  const json base = json::parse(project_text);
  const bool twins = p.compare_intact && !std::get<project::ShaftSection>(p.geometry).layout.failed_pipes.empty();
  std::vector<SectionRun> runs;
  std::vector<std::string> problems;
  for (const double depth : a.depths)
    for (const bool intact : twins ? std::vector<bool>{false, true} : std::vector<bool>{false}) {
      SectionRun s{depth, section_folder(depth, intact), intact, section_document(p, base, a, depth, intact)};
      const std::string source = "section at " + section_name(depth);
      try {
        const auto loaded = project::parse_project(s.project.dump(), source);
        for (const auto& line : geometry::layout_problems(std::get<project::ShaftSection>(loaded.geometry)))
          problems.push_back(source + ": " + line);
      } catch (const project::ProjectError& e) {
        for (const auto& line : e.problems()) problems.push_back(source + ": " + line);
      }
      runs.push_back(std::move(s));
    }
  if (!problems.empty()) throw project::ProjectError(problems);
  return runs;
}

}  // namespace

std::vector<SectionRun> section_runs(const project::Project& p, const std::string& project_text) {
  return section_runs(p, project_text, as_built(p));
}

std::size_t critical_section(const std::vector<json>& entries) {
  const bool margins = !entries.empty() && std::all_of(entries.begin(), entries.end(), [](const json& e) {
    return e.value(keys::design_margin, json()).is_number();
  });
  std::size_t critical = 0;
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < entries.size(); ++k) {
    double badness;
    if (margins) {
      badness = -entries[k][keys::design_margin].get<double>();
    } else {
      const json day = entries[k].value(keys::closure_time_days, json());
      badness = day.is_number() ? day.get<double>() : std::numeric_limits<double>::infinity();
    }
    if (badness >= worst) critical = k, worst = badness;  // ties: the deeper section
  }
  return critical;
}

std::vector<std::string> check_sections(const project::Project& p, const std::string& project_text) {
  io::check_output_directory(p.output.directory);
  const auto runs = section_runs(p, project_text);
  std::vector<std::string> lines{
      fmt::format("as built: {} full-ring sections from {}, one run each", runs.size(), p.survey->file)};
  for (const auto& q : geometry::all_pipe_positions(std::get<project::ShaftSection>(p.geometry).layout))
    lines.push_back(fmt::format("pipe {}: {} at ({:.3f}, {:.3f}) m at the collar{}", q.number, q.label, q.x, q.y,
                                q.failed ? ", failed (off)" : ""));
  // The deepest section placed as the run places it (every section's
  // layout was checked above); the others are the same ring with the pipes
  // moved, of about as many particles.
  const auto& deepest = runs.back();
  for (const auto& line : run::check_project(project::parse_project(deepest.project.dump(), deepest.folder)))
    if (line.rfind("pipe ", 0) != 0) lines.push_back(deepest.folder + ": " + line);
  lines.push_back(fmt::format("sections: {} runs like {}, side by side on the cores (and over the ranks under "
                              "mpirun): on one 2-core machine about {} times its run time in all",
                              runs.size(), deepest.folder, runs.size()));
  return lines;
}

StudyRun run_sections(const project::Project& p, const std::string& project_text, const StudyOptions& options) {
  io::check_output_directory(p.output.directory);
  const fs::path out = p.output.directory;
  const AsBuilt a = as_built(p);
  const auto runs = section_runs(p, project_text, a);
  if (options.note && world_ranks().first())
    options.note(fmt::format("as built: {} sections from {} into {}", runs.size(), p.survey->file, p.output.directory));
  Study study;
  study.name = p.name;
  study.output_directory = out;
  study.estimate_errors = false;  // as the project says
  fs::create_directories(out);
  for (const auto& s : runs) study.variants.push_back({s.folder, s.folder, s.project});
  // With a plant the depths are sections of one brine circuit, run together.
  std::vector<double> depths;
  for (const auto& s : runs) depths.push_back(s.depth);
  CoupledRun coupled;
  if (p.plant) coupled = run_coupled(p, study, depths, options);
  StudyRun run = p.plant ? std::move(coupled.run) : run_study(study, options);
  for (std::size_t k = 0; k < run.variants.size(); ++k)
    if (!run.variants[k].ok)
      throw std::runtime_error(fmt::format("section {}: {}", runs[k].folder,
                                           run.variants[k].errors.empty() ? "failed" : run.variants[k].errors.front()));
  if (!run.writer) return run;

  const double diameter = std::get<project::ShaftSection>(p.geometry).pipe.diameter;
  std::vector<json> entries;
  std::vector<std::size_t> of_entry;  // the variant of each entry
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto pipes = geometry::pipes_at(a.traces, a.design, runs[k].depth);
    const int layer = p.layers.empty() ? -1 : layer_at(p, a, runs[k].depth);
    json entry = section_entry(runs[k], run.variants[k].summary, pipes, diameter,
                               layer >= 0 ? p.layers[layer].name : std::string());
    if (p.plant) entry["brine_temperature"] = coupled.plant["sections"][k]["brine_temperature"];
    if (runs[k].intact) {
      entry.erase("pipes");
      entries.back()["intact"] = entry;
      continue;
    }
    entries.push_back(entry);
    of_entry.push_back(k);
  }
  const std::size_t c = critical_section(entries);
  json summary = run.variants[of_entry[c]].summary;
  summary[keys::project] = p.name;
  for (std::size_t k = 0; k < entries.size(); ++k) entries[k]["critical"] = k == c;
  summary[keys::sections] = entries;
  summary[keys::critical_depth] = entries[c]["depth"];
  if (p.plant) summary[keys::plant] = coupled.plant;
  if (p.excavation) {
    std::vector<json> summaries;
    std::vector<std::string> names;
    for (std::size_t k = 0; k < entries.size(); ++k)
      summaries.push_back(run.variants[of_entry[k]].summary), names.push_back(section_name(entries[k]["depth"]));
    summary[keys::excavation] = excavation_overview(summaries, names);
  }
  json design = json::array();
  for (const auto& q : a.design) design.push_back({q.number, q.x, q.y, q.failed});
  summary[keys::as_built] = {{"survey", p.survey->file},
                             {"form", p.survey->form == project::SurveyForm::positions ? "positions" : "stations"},
                             {"design_pipes", design},
                             {"failed_pipes", std::get<project::ShaftSection>(p.geometry).layout.failed_pipes},
                             {"compare_intact", p.compare_intact}};

  // The 3-D view: each section's last snapshot at its depth, the pipe traces.
  std::vector<io::ShaftVtmSection> placed;
  for (std::size_t k = 0; k < runs.size(); ++k)
    if (!runs[k].intact)
      if (const auto file = last_field_file(out / runs[k].folder))
        placed.push_back({runs[k].depth, *file, "section at " + section_name(runs[k].depth)});
  std::vector<io::ShaftVtmPipe> pipes;
  for (std::size_t k = 0; k < a.design.size(); ++k) {
    io::ShaftVtmPipe pipe{a.design[k].number, a.design[k].failed, {}};
    for (const auto& t : a.traces[k].points)
      if (t.z <= a.traces[k].bottom) pipe.points.push_back({t.x, t.y, t.z});
    const auto end = a.traces[k].at(a.traces[k].bottom);
    pipe.points.push_back({end[0], end[1], a.traces[k].bottom});
    pipes.push_back(std::move(pipe));
  }
  io::write_shaft_vtm(out, placed, pipes);
  io::ParaviewScene scene;
  scene.title = p.name;
  scene.series.push_back({"shaft.vtm", io::ParaviewSeries::Kind::temperature, true});
  scene.freezing_point = p.soil.freezing_point;
  const auto& pipe = std::get<project::ShaftSection>(p.geometry).pipe;
  const auto& cold = p.plant ? p.plant->supply : pipe.temperature;  // the brine the plant supplies, or the pipe's
  scene.coldest = std::min(cold.points.empty() ? 0.0 : cold.at(0.0), p.soil.freezing_point);
  for (const auto& [t, T] : cold.points) scene.coldest = std::min(scene.coldest, T);
  scene.warmest = std::max(p.domain.initial_temperature, p.domain.far_field_temperature.value_or(-1e300));
  scene.isotherm = p.design.isotherm;
  io::write_paraview_script(out / "open_in_paraview.py", scene);
  write_joined_run(p, project_text, summary);
  return run;
}

}  // namespace frostwall::study
