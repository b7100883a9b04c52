// What a heat run writes at its output times: the sample times, the names
// of the snapshot files, and the VTK frames (the simulated section, and the
// whole ring unfolded from its symmetry wedge for ParaView).
#pragma once

#include <string>
#include <vector>

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
// the temperature, liquid fraction and phase only).
io::PointCloudFrame full_ring(const io::PointCloudFrame& wedge, const std::vector<particles::MirrorPlane<2>>& mirrors,
                              double length_scale);

const char* integrator_name(project::IntegratorKind k);
const char* time_unit_name(project::TimeUnit u);

}  // namespace frostwall::freezing
