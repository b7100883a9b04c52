// The shaft as built (as_built.hpp): the survey file, the section depths
// and the failed pipes. The survey file is read here, at the edge, into
// rows; desurveying and the geometric checks are lib/geometry's.
#include "project/load_survey.hpp"

#include "project/csv_cells.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <set>
#include <sstream>

namespace frostwall::project {

int pipe_count(const Layout& layout) {
  const int outer = std::max(0, layout.outer_ring.count);
  switch (layout.pattern) {
    case Pattern::single: return outer;
    case Pattern::three_hole: return layout.inner_ring_radius ? 2 * outer : outer;
    case Pattern::four_hole: return layout.inner_ring_radius ? 3 * outer : outer;
    case Pattern::rings: {
      int n = 0;
      for (const auto& r : layout.rings) n += std::max(0, r.count);
      return n;
    }
    case Pattern::pipes: return static_cast<int>(layout.pipes.size());
  }
  return 0;
}

namespace detail {

namespace {

// The rows of a survey file into `survey`; each problem as "line N: ...".
void read_rows(std::istream& in, int pipes, Survey& survey, std::vector<std::string>& problems) {
  std::string line;
  int number = 0;
  const std::vector<std::string> positions{"pipe", "depth", "x", "y"};
  const std::vector<std::string> stations{"pipe", "depth", "inclination_deg", "azimuth_deg"};
  while (std::getline(in, line) && ++number && line.find_first_not_of(" \t\r") == std::string::npos) {
  }
  const auto header = split_cells(line);
  if (header == positions) survey.form = SurveyForm::positions;
  else if (header == stations) survey.form = SurveyForm::stations;
  else {
    problems.push_back(fmt::format("line {}: the header must be pipe,depth,x,y or pipe,depth,inclination_deg,"
                                   "azimuth_deg, got '{}'",
                                   number, line));
    return;
  }
  survey.pipes.assign(std::max(0, pipes), {});
  const auto& names = survey.form == SurveyForm::positions ? positions : stations;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto cells = split_cells(line);
    if (cells.size() != 4) {
      problems.push_back(fmt::format("line {}: expected 4 cells ({}), got {}", number, line, cells.size()));
      continue;
    }
    std::optional<double> v[4];
    bool ok = true;
    for (int c = 0; c < 4; ++c)
      if (!(v[c] = parse_number(cells[c])))
        problems.push_back(fmt::format("line {}: {} '{}' is not a number", number, names[c], cells[c])), ok = false;
    if (!ok) continue;
    const double p = *v[0];
    if (p != std::floor(p) || p < 1 || p > pipes) {
      problems.push_back(fmt::format("line {}: pipe {} does not exist (the layout has pipes 1 to {}, numbered as "
                                     "`frostwall check` lists them)",
                                     number, cells[0], pipes));
      continue;
    }
    SurveyRow row{number, *v[1], *v[2], *v[3]};
    if (row.depth < 0)
      problems.push_back(fmt::format("line {}: depth {} is negative (metres below the collar)", number, cells[1]));
    if (survey.form == SurveyForm::stations && (row.a < 0 || row.a > 90))
      problems.push_back(
          fmt::format("line {}: inclination {} is outside 0 to 90 degrees (from the vertical)", number, cells[2]));
    auto& rows = survey.pipes[static_cast<std::size_t>(p) - 1];
    if (!rows.empty() && row.depth <= rows.back().depth)
      problems.push_back(fmt::format("line {}: pipe {}'s depth {} does not increase (line {} has {})", number, cells[0],
                                     cells[1], rows.back().line, rows.back().depth));
    rows.push_back(row);
  }
  std::vector<int> missing;
  for (std::size_t k = 0; k < survey.pipes.size(); ++k)
    if (survey.pipes[k].empty()) missing.push_back(static_cast<int>(k) + 1);
  if (!missing.empty())
    problems.push_back(fmt::format("pipe{} {} {} missing (every pipe of the layout needs at least one row)",
                                   missing.size() > 1 ? "s" : "", fmt::join(missing, ", "),
                                   missing.size() > 1 ? "are" : "is"));
}

}  // namespace

std::optional<Survey> read_survey(const Node& n, const Layout& layout, const std::string& base_directory) {
  if (!n.present() || !n.object({"file", "pipe_depth"})) return std::nullopt;
  Survey survey;
  const auto file = n["file"].required().string();
  if (n["pipe_depth"].present()) survey.pipe_depth = n["pipe_depth"].positive();
  if (!file) return std::nullopt;
  survey.file = *file;
  survey.path = resolve_path(*file, base_directory);
  std::ifstream in(survey.path, std::ios::binary);
  if (!in) {
    n["file"].problem(fmt::format("cannot read {}: {}", survey.path, std::strerror(errno)));
    return std::nullopt;
  }
  std::vector<std::string> problems;
  read_rows(in, pipe_count(layout), survey, problems);
  for (const auto& p : problems) n["file"].problem(survey.file + " " + p);
  if (!problems.empty()) return std::nullopt;
  return survey;
}

Sections read_sections(const Node& n) {
  Sections sections;
  if (!n.present() || !n.object({"depths", "every"})) return sections;
  if (n["depths"].present() && n["every"].present()) n.problem(R"(give "depths" or "every", not both)");
  if (n["every"].present()) sections.every = n["every"].positive();
  if (const auto size = n["depths"].array()) {
    if (*size == 0) n["depths"].problem("must list at least one depth");
    for (std::size_t k = 0; k < *size; ++k)
      if (const auto d = n["depths"][k].non_negative()) {
        if (!sections.depths.empty() && *d <= sections.depths.back())
          n["depths"][k].problem(fmt::format("depths must increase ({} after {})", *d, sections.depths.back()));
        sections.depths.push_back(*d);
      }
  }
  return sections;
}

std::vector<int> read_failed_pipes(const Node& n, const Layout& layout) {
  std::vector<int> failed;
  if (!n.present()) return failed;
  const auto size = n.array();
  if (!size) return failed;
  const int count = pipe_count(layout);
  std::set<int> seen;
  for (std::size_t k = 0; k < *size; ++k) {
    const auto v = n[k].count();
    if (!v) continue;
    if (*v > count) n[k].problem(fmt::format("pipe {} does not exist (the layout has pipes 1 to {})", *v, count));
    else if (!seen.insert(*v).second) n[k].problem(fmt::format("pipe {} is listed twice", *v));
    else failed.push_back(*v);
  }
  if (count > 0 && static_cast<int>(failed.size()) >= count) n.problem("at least one pipe must work");
  return failed;
}

}  // namespace detail

}  // namespace frostwall::project
