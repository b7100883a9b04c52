#include "geometry/survey.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frostwall::geometry {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

std::array<double, 3> direction(double inclination_deg, double azimuth_deg) {
  const double I = inclination_deg * deg, A = azimuth_deg * deg;
  return {std::sin(I) * std::sin(A), std::sin(I) * std::cos(A), std::cos(I)};
}

}  // namespace

std::vector<std::array<double, 3>> minimum_curvature(std::array<double, 3> start,
                                                     const std::vector<std::array<double, 3>>& stations) {
  std::vector<std::array<double, 3>> out;
  if (stations.empty()) return out;
  // The collar carries the first station's direction.
  double md = 0.0;
  auto t1 = direction(stations.front()[1], stations.front()[2]);
  auto p = start;
  for (const auto& s : stations) {
    const auto t2 = direction(s[1], s[2]);
    const double cosb = std::clamp(t1[0] * t2[0] + t1[1] * t2[1] + t1[2] * t2[2], -1.0, 1.0);
    const double b = std::acos(cosb);
    const double rf = b < 1e-9 ? 1.0 : 2.0 / b * std::tan(b / 2.0);
    const double half = 0.5 * (s[0] - md) * rf;
    for (int c = 0; c < 3; ++c) p[c] += half * (t1[c] + t2[c]);
    out.push_back(p);
    md = s[0], t1 = t2;
  }
  return out;
}

std::array<double, 2> PipeTrace::at(double z) const {
  const auto& P = points;
  if (P.size() == 1) return {P[0].x, P[0].y};
  // The segment holding z, or the last one (extrapolated beyond it).
  std::size_t k = 1;
  while (k + 1 < P.size() && P[k].z < z) ++k;
  const auto &a = P[k - 1], &b = P[k];
  const double s = b.z > a.z ? (z - a.z) / (b.z - a.z) : 0.0;
  return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
}

std::vector<PipeTrace> pipe_traces(const project::Survey& survey, const std::vector<Pipe2>& design) {
  std::vector<PipeTrace> traces(design.size());
  for (std::size_t k = 0; k < design.size() && k < survey.pipes.size(); ++k) {
    auto& trace = traces[k];
    const auto& rows = survey.pipes[k];
    trace.points.push_back({0.0, design[k].x, design[k].y, 0});
    if (survey.form == project::SurveyForm::positions) {
      for (const auto& r : rows) {
        if (r.depth == 0.0) trace.points.front() = {0.0, r.a, r.b, r.line};
        else trace.points.push_back({r.depth, r.a, r.b, r.line});
      }
    } else {
      std::vector<std::array<double, 3>> stations;
      for (const auto& r : rows) stations.push_back({r.depth, r.a, r.b});
      const auto at = minimum_curvature({design[k].x, design[k].y, 0.0}, stations);
      for (std::size_t i = 0; i < at.size(); ++i)
        if (rows[i].depth > 0.0) trace.points.push_back({at[i][2], at[i][0], at[i][1], rows[i].line});
    }
    // The nominal depth of the last row (for stations a measured depth, which
    // the trace reaches by going on along its last direction).
    trace.bottom = survey.pipe_depth.value_or(rows.empty() ? 0.0 : rows.back().depth);
  }
  return traces;
}

}  // namespace frostwall::geometry
