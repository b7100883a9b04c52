#include "freezing/output_frames.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <stdexcept>

#include "particles/symmetry_group.hpp"

namespace frostwall::freezing {

std::vector<double> sample_times(const project::TimeSettings& time, std::size_t regular) {
  std::vector<double> t = time.snapshots;
  for (std::size_t k = 1; k <= regular; ++k) t.push_back(time.end * k / regular);
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end(), [&](double a, double b) { return std::abs(a - b) <= 1e-12 * time.end; }),
          t.end());
  return t;
}

std::vector<std::string> snapshot_stems(const project::TimeSettings& time, const std::string& prefix) {
  const double u = time.unit_seconds();
  bool whole = true;
  for (double t : time.snapshots) whole = whole && std::abs(t / u - std::round(t / u)) < 1e-9;
  std::vector<std::string> stems;
  for (std::size_t k = 0; k < time.snapshots.size(); ++k)
    stems.push_back(fmt::format("{}_{:04d}", prefix, whole ? std::lround(time.snapshots[k] / u) : long(k + 1)));
  return stems;
}

io::PointCloudFrame frame_of(const particles::ParticleSet<2>& particles, const thermal::ThermalModel& model) {
  io::PointCloudFrame frame;
  const std::size_t n = particles.size();
  frame.points.reserve(n);
  for (const auto& x : particles.position) frame.points.push_back({x[0], x[1], 0.0});
  std::vector<double> phase(n), k(n), boundary(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double f = model.liquid_fraction()[i];
    phase[i] = f <= 0.0 ? -1.0 : (f >= 1.0 ? 1.0 : 0.0);  // the paper's flag: -1 frozen, 0 freezing, +1 unfrozen
    k[i] = 0.5 * (model.conductivity(i, 0) + model.conductivity(i, 1));
    boundary[i] = particles.boundary[i];
  }
  frame.fields = {{"temperature", model.temperature()},
                  {"enthalpy", model.enthalpy()},
                  {"liquid_fraction", model.liquid_fraction()},
                  {"phase", phase},
                  {"conductivity", k},
                  {"volume", particles.volume},
                  {"boundary", boundary}};
  return frame;
}

io::PointCloudFrame full_ring(const io::PointCloudFrame& wedge, const std::vector<particles::MirrorPlane<2>>& mirrors,
                              double length_scale) {
  const auto group = particles::symmetry_group(mirrors, length_scale);
  io::PointCloudFrame ring;
  ring.single_precision = true;  // 50x the wedge's particles: float32 halves the file and its write time
  ring.labels = wedge.labels;
  for (const auto& field : wedge.fields)
    if (field.first == "temperature" || field.first == "liquid_fraction" || field.first == "phase" ||
        field.first == "boundary")
      ring.fields.push_back(field);
  for (auto& field : ring.fields) field.second.clear();
  for (const auto& g : group) {
    for (const auto& x : wedge.points) {
      const particles::Vec<2> y = g(particles::Vec<2>(x[0], x[1]));
      ring.points.push_back({y[0], y[1], 0.0});
    }
    for (auto& field : ring.fields)
      for (const auto& source : wedge.fields)
        if (source.first == field.first)
          field.second.insert(field.second.end(), source.second.begin(), source.second.end());
  }
  return ring;
}

std::vector<geometry::Triangle> ground_triangles(const std::vector<particles::Vec<2>>& points,
                                                 const std::vector<double>& limit, const std::vector<double>& boundary,
                                                 bool shaft) {
  auto all = geometry::cloud_triangles(points, limit);
  if (shaft)
    std::erase_if(all, [&](const geometry::Triangle& t) {
      return boundary[t[0]] >= 0 && boundary[t[1]] >= 0 && boundary[t[2]] >= 0;
    });
  // Smallest corner first (the orientation kept), triangles in the order of
  // their corners: neighbouring numbers compress to a fraction of the size.
  for (auto& t : all) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(all.begin(), all.end());
  return all;
}

bool shown_in_files(const particles::ParticleSet<2>& P, std::size_t i,
                    const std::optional<std::array<double, 2>>& plate) {
  if (P.is_free(i)) return true;
  if (P.reflection[i].allFinite()) return false;  // a layer beyond a wall
  const auto& x = P.position[i];
  const double tol = 1e-9 * P.spacing;
  return !plate || (x[0] >= -tol && x[0] <= (*plate)[0] + tol && x[1] >= -tol && x[1] <= (*plate)[1] + tol);
}

SnapshotFrames::SnapshotFrames(const particles::ParticleSet<2>& P, io::Labels labels,
                               std::optional<std::array<double, 2>> plate)
    : labels_(std::move(labels)) {
  for (std::size_t i = 0; i < P.size(); ++i)
    if (shown_in_files(P, i, plate)) shown_.push_back(i);
  std::vector<particles::Vec<2>> points;
  std::vector<double> limit, boundary;
  for (std::size_t i : shown_)
    points.push_back(P.position[i]), limit.push_back(3.0 * P.spacing_of(i)), boundary.push_back(P.boundary[i]);
  wedge_triangles_ = ground_triangles(points, limit, boundary, !plate);
}

io::PointCloudFrame SnapshotFrames::wedge(const io::PointCloudFrame& all) const {
  auto frame = io::subset(all, shown_);
  frame.triangles = wedge_triangles_;
  frame.labels = labels_;
  return frame;
}

const char* integrator_name(project::IntegratorKind k) {
  if (k == project::IntegratorKind::rkl2) return "rkl2";
  return k == project::IntegratorKind::implicit ? "implicit" : "explicit";
}

}  // namespace frostwall::freezing
