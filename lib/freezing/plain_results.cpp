#include "freezing/plain_results.hpp"

#include <cmath>
#include <fmt/core.h>

#include "io/atomic_file.hpp"
#include "io/polyline_vtk.hpp"
#include "particles/mirror_images.hpp"
#include "freezing/heat_run.hpp"
#include "summary/summary.hpp"

namespace frostwall::freezing {

namespace keys = summary::keys;

namespace {
using nlohmann::json;
using Vec2 = particles::Vec<2>;

// Points every half spacing from `from` to `to`, both included.
std::vector<Vec2> along(const project::FrontLine& line, double step) {
  const Vec2 a(line.from_x, line.from_y), b(line.to_x, line.to_y);
  const auto n = static_cast<std::size_t>(std::ceil((b - a).norm() / step));
  std::vector<Vec2> points;
  for (std::size_t k = 0; k <= n; ++k) points.push_back(a + (b - a) * (static_cast<double>(k) / n));
  return points;
}
}  // namespace

std::optional<double> first_crossing(const std::vector<double>& values, double step) {
  for (std::size_t k = 1; k < values.size(); ++k) {
    const double a = values[k - 1], b = values[k];
    if (std::isnan(a) || std::isnan(b)) continue;
    if ((a <= 0.5) != (b <= 0.5)) return (k - 1 + (0.5 - a) / (b - a)) * step;
  }
  return std::nullopt;
}

PlainResults::PlainResults(const project::Project& p, const Model& m)
    : project_(p),
      model_(m),
      unit_(p.time.unit_seconds()),
      sampler_(m.particles(), *m.kernel, m.smoothing),
      sensors_(std::make_unique<Thermometers>(p, m)) {
  const double step = 0.5 * m.particles().spacing;
  for (const auto& line : p.output.front_along) {
    // (snapshot() reads the step back from the points: the segment is split into whole steps.)
    lines_.push_back(std::make_unique<post::PointProbe>(sampler_, along(line, step)));
  }
  const auto& P = m.particles();
  curve_points_ = P.position;
  for (std::uint32_t i = 0; i < P.size(); ++i) curve_source_.push_back(i);
  const auto images = particles::mirror_images(P, 3.0 * P.coarsest_spacing());
  curve_points_.insert(curve_points_.end(), images.position.begin(), images.position.end());
  curve_source_.insert(curve_source_.end(), images.source.begin(), images.source.end());
}

PlainResults::~PlainResults() = default;

void PlainResults::attach(const SolidView* solid) {
  mechanics_ = solid;
  std::vector<Vec2> where;
  for (const auto& s : project_.monitoring) where.emplace_back(s.x, s.y);
  const auto& P = model_.particles();
  const std::vector<Vec2> free(P.position.begin(), P.position.begin() + P.n_free);
  solid_sensors_ = std::make_unique<post::LinearProbe>(free, where, 2.5 * P.spacing);
}

void PlainResults::sample(double t, const thermal::ThermalModel& model) {
  if (project_.monitoring.empty()) return;
  times_.push_back(t / unit_);
  readings_.push_back(sensors_->read(model.temperature()));
  if (!mechanics_) return;
  const auto& u = mechanics_->displacement();
  const auto damage = mechanics_->damage();
  std::vector<std::array<double, 3>> row;
  for (std::size_t k = 0; k < solid_sensors_->size(); ++k)
    row.push_back({solid_sensors_->at(k, u, 2, 0), solid_sensors_->at(k, u, 2, 1), solid_sensors_->at(k, damage)});
  solid_readings_.push_back(row);
}

void PlainResults::snapshot(double t, const thermal::ThermalModel& model, const std::filesystem::path& out,
                            const std::string& stem) {
  for (std::size_t l = 0; l < lines_.size(); ++l) {
    const auto& line = project_.output.front_along[l];
    const auto& points = lines_[l]->points();
    const double step = points.size() > 1 ? (points[1] - points[0]).norm() : 0.0;
    const auto d = first_crossing((*lines_[l])(model.liquid_fraction()), step);
    front_along_.push_back({{"from", {line.from_x, line.from_y}},
                            {"to", {line.to_x, line.to_y}},
                            {"t", t / unit_},
                            {"distance", d ? json(*d) : json(nullptr)}});
  }
  const auto& P = model_.particles();
  if (!curve_mesh_) curve_mesh_ = std::make_unique<post::IsolineMesh>(curve_points_, 3.0 * P.coarsest_spacing());
  std::vector<double> f(curve_source_.size());
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = model.liquid_fraction()[curve_source_[k]];
  const auto& rect = *std::get_if<project::Rectangle>(&project_.geometry);
  const auto kept = post::clip_polylines(curve_mesh_->isolines(f, 0.5), [&](const Vec2& x) {
    return x[0] >= 0.0 && x[0] <= rect.width && x[1] >= 0.0 && x[1] <= rect.height;
  });
  const std::string file = "interface" + stem.substr(5) + ".vtp";
  io::write_vtp(out / file, kept, io::file_labels(project_));
  interface_.push_back({{"t", t / unit_}, {"file", file}});
}

json PlainResults::finish(const std::filesystem::path& out) const {
  json result;
  json monitoring = json::object();
  for (std::size_t s = 0; s < project_.monitoring.size(); ++s) {
    json series = json::array();
    for (std::size_t k = 0; k < times_.size(); ++k) series.push_back({times_[k], readings_[k][s]});
    monitoring[project_.monitoring[s].name] = series;
  }
  result[keys::monitoring] = monitoring;
  if (mechanics_) {
    json solid = json::object();
    for (std::size_t s = 0; s < project_.monitoring.size(); ++s) {
      json series = json::array();
      for (std::size_t k = 0; k < times_.size(); ++k)
        series.push_back({times_[k], solid_readings_[k][s][0], solid_readings_[k][s][1], solid_readings_[k][s][2]});
      solid[project_.monitoring[s].name] = series;
    }
    result[keys::monitoring_solid] = solid;  // [t, ux m, uy m, damage]
  }
  result[keys::front_along] = front_along_;
  result[keys::interface] = interface_;
  if (!project_.monitoring.empty()) {
    std::string csv = "time";
    for (const auto& s : project_.monitoring) {
      csv += "," + s.name + "_C";
      if (mechanics_) csv += "," + s.name + "_ux_m," + s.name + "_uy_m," + s.name + "_damage";
    }
    csv += "\n";
    for (std::size_t k = 0; k < times_.size(); ++k) {
      csv += fmt::format("{:.6g}", times_[k]);
      for (std::size_t s = 0; s < readings_[k].size(); ++s) {
        csv += fmt::format(",{:.6g}", readings_[k][s]);
        if (mechanics_)
          csv += fmt::format(",{:.6g},{:.6g},{:.6g}", solid_readings_[k][s][0], solid_readings_[k][s][1],
                             solid_readings_[k][s][2]);
      }
      csv += "\n";
    }
    io::write_text_file(out / "monitoring.csv", csv);
  }
  return result;
}

}  // namespace frostwall::freezing
