// The results of a porous plate that freezes (frost damage): when each
// pore starts and ends freezing, the damage after every mechanical
// equilibrium (damage.csv) and at each snapshot (the summary's "damage"),
// each pore's largest rim damage, the crack lines (the damage-0.4
// isoline, cracks_XXXX.vtp) and the pore id and material of each particle
// for the VTU files.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/point_cloud_vtk.hpp"
#include "post/isoline.hpp"
#include "project/project.hpp"
#include "mechanics/mechanics_run.hpp"
#include "freezing/model.hpp"

namespace frostwall::mechanics {

using freezing::Model;

// Damage of the solid at one time.
struct DamageState {
  double broken_bond_share = 0.0;   // broken / all bonds between material points
  double largest_damage = 0.0;      // of a material point
  double damaged_area = 0.0;        // m2 per metre of depth with damage above crack_damage
  double broken_bond_energy = 0.0;  // J per metre of depth: the work to break the broken bonds
};

// The crack lines at one time: the damage-0.4 isolines' total length (m
// per metre of depth; a thin crack band is bounded by two such lines, so
// this is about twice the crack's own length) and that per unit area of
// the plate (1/m).
struct CrackMeasure {
  double length = 0.0, per_area = 0.0;
};
CrackMeasure crack_measure(const std::vector<geometry::Polyline>& lines, double area);

class FrostResults {
 public:
  static constexpr double crack_damage = 0.4;  // a point this damaged is cracked (the crack lines' level)

  // mechanics may be null (a thermal run of a porous plate).
  FrostResults(const project::Project& p, const Model& m, const MechanicsRun* mechanics);
  ~FrostResults();
  // After every thermal step: the pores' freezing.
  void after_step(const thermal::ThermalModel& model, double t);
  // After every mechanical equilibrium.
  void after_equilibrium(double t);
  // At each snapshot: the damage record and the crack lines (stem "field_0001").
  void snapshot(double t, const std::filesystem::path& out, const std::string& stem);
  // pore_id (-1: matrix) and material (0 matrix, 1 water, 2 ice) on a frame.
  void add_fields(io::PointCloudFrame& frame, const thermal::ThermalModel& model) const;
  // Summary entries ("pores", "pores_generated", "all_pores_frozen",
  // "damage", "broken_bonds_near_rims"); writes damage.csv.
  nlohmann::json finish(const std::filesystem::path& out) const;

  DamageState damage_now() const;
  // Share of the broken bonds whose midpoint lies within one pore radius
  // of that pore's rim (outside it); nullopt when none broke.
  std::optional<double> broken_near_rims() const;
  // Each pore's crack reach (m): the farthest cracked point (damage above
  // crack_damage) from its rim among the points whose nearest rim it is;
  // 0 when none.
  std::vector<double> crack_reach() const;
  // The crack lines' measure now.
  CrackMeasure crack_measure_now() const { return crack_measure(crack_lines(), rect_.width * rect_.height); }
  // Each pore's frozen fraction now, and its freezing start and end (s).
  const std::vector<double>& frozen() const { return frozen_; }
  const std::vector<std::optional<double>>& freezing_start() const { return start_; }
  const std::vector<std::optional<double>>& freezing_end() const { return end_; }

 private:
  std::vector<double> rim_damage() const;               // largest damage within a horizon outside each rim
  std::vector<geometry::Polyline> crack_lines() const;  // the damage isolines at crack_damage

  const project::Project& project_;
  const project::Rectangle& rect_;
  const Model& model_;
  const MechanicsRun* mechanics_;
  double unit_;
  std::vector<double> frozen_;
  std::vector<std::optional<double>> start_, end_;
  std::vector<std::array<double, 5>> history_;  // t (s), broken share, largest damage, damaged area, energy
  nlohmann::json damage_ = nlohmann::json::array(), cracks_ = nlohmann::json::array();
  std::unique_ptr<post::IsolineMesh> mesh_;
};

}  // namespace frostwall::mechanics
