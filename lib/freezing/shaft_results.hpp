// The engineering results of a shaft run, gathered while it runs: wall
// extents on OA, OB and the weakest ray, the mean wall temperature on OB,
// temperature profiles along OA and OB, sensor readings, the design check
// and the frozen-front curves. Turned into summary.json entries and CSV
// files at the end (project-format.md section 2).
#pragma once

#include "post/isoline.hpp"

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "post/field_sampler.hpp"
#include "post/wall_extent.hpp"
#include "project/project.hpp"
#include "freezing/design_check.hpp"
#include "freezing/excavation_run.hpp"
#include "freezing/model.hpp"
#include "geometry/interface_planes.hpp"

namespace frostwall::freezing {

using geometry::InterfacePlanes;
using geometry::interface_planes;

class ShaftResults {
 public:
  ShaftResults(const project::Project& p, const Model& m);
  ~ShaftResults();

  // Every output interval: the liquid fraction and temperature of every
  // particle at t (the model's state, or one interpolated between steps),
  // and the sensors' readings then (freezing/thermometers.hpp).
  void sample(double t, const std::vector<double>& liquid_fraction, const std::vector<double>& temperature,
              const std::vector<double>& sensors);
  void snapshot(double t, const thermal::ThermalModel& model, const std::filesystem::path& out,
                const std::string& stem);  // at each snapshot day
  // From now on the ground begins at the excavation's face: the wall is
  // measured from there outward, on the liquid fraction as the excavation
  // reads it (ExcavationRun::as_ground), and the front curves drawn on it
  // as shown (ExcavationRun::as_shown).
  void set_face(const ExcavationRun& excavation);
  // A reading of the wall at t outside the regular series (the moment a
  // section is dug or lined), for excavation_entry.
  void read_event(double t, const std::vector<double>& liquid_fraction, const std::vector<double>& temperature) {
    event_readings_.push_back(read(t, liquid_fraction, temperature));
  }
  // The section's wall after its excavation day (readings of the regular
  // series from that day on): thickness, mean temperature, required
  // thickness and margin = thickness - required, with the thinnest wall and
  // the smallest margin and their days (excavation.sections[k] of the
  // summary); the readings at the excavation's events among them.
  nlohmann::json excavation_entry(double day) const;
  // Summary entries (wall, design, monitoring, interface) and the CSV files.
  nlohmann::json finish(const std::filesystem::path& out) const;
  // The whole ring's triangles (once a snapshot has built them; else
  // nullptr), over the copies of the particles the snapshot files show, in
  // the order of the ring files: shared with them.
  const std::vector<geometry::Triangle>* ring_triangles() const {
    return ring_mesh_ ? &ring_mesh_->triangles() : nullptr;
  }

 private:
  nlohmann::json wall_entries(std::optional<DesignMet>& met) const;
  nlohmann::json design_entry(const std::optional<DesignMet>& met) const;
  void write_tables(const std::filesystem::path& out) const;
  struct Reading {
    double day;
    post::FrozenStretch OA, OB;
    double min_thickness;
    std::optional<double> mean_temperature_OB;
    std::optional<double> mean_temperature_thinnest;  // the thinnest ray's frozen stretch
    // With a design isotherm: the thinnest wall colder than it, and its mean temperature.
    std::optional<double> isotherm_thickness, isotherm_mean_temperature;
    // Under seepage: the thinnest ray within 60 degrees of against (upstream)
    // and along (downstream) the flow.
    std::optional<double> upstream_thickness, downstream_thickness;
    double weakest_angle_deg = 0.0;  // the thinnest ray, or the middle of the open gap (post::weakest_angle)
  };
  // The wall check of a reading: on the design isotherm when there is one.
  WallCheck check(const Reading& r) const;
  Reading read(double t, const std::vector<double>& liquid_fraction, const std::vector<double>& temperature) const;

  const project::Project& project_;
  const Model& model_;
  const ExcavationRun* excavation_ = nullptr;  // once dug
  InterfacePlanes planes_;
  post::FieldSampler sampler_;
  std::unique_ptr<post::WallGauge> fan_gauge_, planes_gauge_;
  std::unique_ptr<post::PointProbe> profile_OA_, profile_OB_;
  std::vector<double> profile_radii_;
  // Profile points inside a pipe disc (OA passes through its pipe): they
  // read the pipe's temperature, not the layers held beyond its wall.
  std::vector<char> in_pipe_OA_, in_pipe_OB_;
  std::vector<Reading> series_, snapshots_, event_readings_;
  std::vector<std::vector<double>> profiles_OA_, profiles_OB_;  // per snapshot
  std::vector<std::vector<std::pair<double, double>>> sensor_readings_;
  nlohmann::json interface_ = nlohmann::json::array();
  // Points for the front curves: the particles and their mirror images
  // (wedge), and the copies of the particles the files show around the ring
  // (full ring), with the source index. Triangulated at the first snapshot,
  // reused for every later one.
  std::vector<particles::Vec<2>> curve_points_, ring_points_;
  std::vector<std::uint32_t> curve_source_, ring_source_;
  std::unique_ptr<post::IsolineMesh> curve_mesh_, ring_mesh_;
};

}  // namespace frostwall::freezing
