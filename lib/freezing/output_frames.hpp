// What a heat run writes at its output times: the sample times, the names
// of the snapshot files, and the VTK frames (the simulated section, and the
// whole ring unfolded from its symmetry wedge for ParaView).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "geometry/cloud_mesh.hpp"
#include "io/point_cloud_vtk.hpp"
#include "particles/particle_set.hpp"
#include "project/project.hpp"
#include "thermal/thermal_model.hpp"

namespace frostwall::freezing {

// Output times: the snapshots, plus `regular` evenly spaced samples for the
// time curves.
std::vector<double> sample_times(const project::TimeSettings& time, std::size_t regular);

// Snapshot files are named by their time in the project's unit when those
// are whole numbers (field_0010.vtu for day 10), else by their number.
std::vector<std::string> snapshot_stems(const project::TimeSettings& time, const std::string& prefix);

// The thermal fields of every particle (free and fixed).
io::PointCloudFrame frame_of(const particles::ParticleSet<2>& particles, const thermal::ThermalModel& model);

// The whole ring: every copy of the wedge under its mirror group (float32,
// the temperature, liquid fraction, phase and boundary flag only).
io::PointCloudFrame full_ring(const io::PointCloudFrame& wedge, const std::vector<particles::MirrorPlane<2>>& mirrors,
                              double length_scale);

// Whether particle i is written to the snapshot files (below): free, or
// fixed with the boundary's own temperature and on the plate (plate: its
// width and height; nullopt: a shaft section).
bool shown_in_files(const particles::ParticleSet<2>& P, std::size_t i,
                    const std::optional<std::array<double, 2>>& plate);

// The cloud's triangles at most `limit` (per point) long; in a shaft
// section (shaft true) without those whose three corners all hold a
// boundary temperature (boundary >= 0): they lie across a pipe disc.
// Sorted (smallest corner first, then by corners) so files compress well.
std::vector<geometry::Triangle> ground_triangles(const std::vector<particles::Vec<2>>& points,
                                                 const std::vector<double>& limit, const std::vector<double>& boundary,
                                                 bool shaft);

// What a user sees of the particles in the snapshot files:
//  - the free particles and the fixed ones that hold a boundary's own
//    temperature on the domain (on a pipe wall, a cooled face, a point-model
//    pipe), not the layers beyond a wall that hold its antisymmetric
//    extension (colder than the wall itself, inside the pipe discs), nor
//    the fixed layers outside a plate;
//  - the triangles between them (the cloud's Delaunay triangles, at most
//    three local spacings long; in a shaft section, not those whose three
//    corners all hold a boundary temperature: across a pipe disc), so
//    ParaView contours the field with no preparation. Built once: the
//    particles do not move.
// The whole ring's files get the triangles of all copies of the wedge's
// shown particles, which the shaft results build for the ring's front
// curves (ShaftResults::ring_triangles).
class SnapshotFrames {
 public:
  // labels: the field data of every file (project, time unit, version);
  // plate: the rectangle's width and height (m), or nullopt for a shaft
  // section.
  SnapshotFrames(const particles::ParticleSet<2>& particles, io::Labels labels,
                 std::optional<std::array<double, 2>> plate);
  // The shown particles of a frame of every particle (frame_of plus what
  // the run added to it), with their triangles.
  io::PointCloudFrame wedge(const io::PointCloudFrame& all) const;
  std::size_t shown() const { return shown_.size(); }

 private:
  std::vector<std::size_t> shown_;
  io::Labels labels_;
  std::vector<geometry::Triangle> wedge_triangles_;
};

const char* integrator_name(project::IntegratorKind k);

}  // namespace frostwall::freezing
