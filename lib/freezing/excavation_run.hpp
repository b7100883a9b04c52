// The excavation of one shaft section during its heat run: on the section's
// day the ground inside the excavation radius is taken out (its heat
// leaves the model with it) and the face meets the shaft's air through its
// film (freezing/excavation_face.hpp); after `placed_after_days` the lining
// takes the place of the ground just inside the radius, at its placing
// temperature, and gives off its cement's heat as it sets; the air then
// meets the lining's inner face. Every heat that enters or leaves the model
// this way is counted, so the run's heat balance still closes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "freezing/excavation_face.hpp"
#include "freezing/model.hpp"
#include "project/project.hpp"

namespace frostwall::freezing {

class ExcavationRun {
 public:
  ExcavationRun(const project::Project& p, Model& m);
  // The time (s) of the next change (the dig, the lining); infinity once done.
  double next_event() const;
  // Makes the change due at t (t = next_event()).
  void apply(double t);
  // After each step: the lining's heat of hydration to t, and the ground
  // taken out shown at the face's temperature (it no longer counts).
  void after_step(double t);
  // The liquid fraction the wall is measured on: each particle that is no
  // longer ground (taken out, or the lining) reads as the face particle
  // nearest its direction, so a frozen face reaches the excavation radius
  // and a thawed one does not.
  void as_ground(std::vector<double>& liquid_fraction) const;
  // The liquid fraction the front curves are drawn on: what is no longer
  // ground is never frozen, so the front runs along the face.
  void as_shown(std::vector<double>& liquid_fraction) const;
  // The longest next step: a fifth of the hydration's release time while
  // the lining sets (none otherwise).
  double step_limit() const;

  double day() const;          // the section's excavation day
  double face_radius() const;  // m: the ground's face (the excavation radius)
  // The summary's `excavation`: the section's facts (depth, days, particles)
  // with the wall after the day (ShaftResults::excavation_entry), and the
  // shaft's sections (excavation_overview): this one, critical. Writes its
  // series as <out>/excavation.csv.
  nlohmann::json summary(const nlohmann::json& wall_after, const std::filesystem::path& out) const;
  // The heat balance's entries: excavated, lining_placed, hydration.
  void add_heat(nlohmann::json& from_boundaries) const;

 private:
  void dig(double t);
  void line(double t);
  // Joins the particles of `side` near radius a to the face, the face's
  // earlier pairs cut; the face's film then over that circle. Returns the
  // face's particles and weights.
  std::vector<FaceWeight> join_face(double a, const std::vector<char>& side);
  void stability_changed();
  nlohmann::json facts() const;

  const project::Project& p_;
  const project::Excavation& e_;
  Model& m_;
  double radius_ = 0.0;  // the excavation radius
  double share_ = 1.0;   // the part of the circle in the section
  int face_boundary_ = -1;
  std::uint32_t node_ = 0;
  bool dug_ = false, lined_ = false;
  double now_ = 0.0, lined_at_ = 0.0, released_ = 0.0;
  std::vector<std::uint32_t> taken_, lining_;  // taken out (the lining's among them); the lining
  std::vector<FaceWeight> face_;               // the particles joined to the face now
  std::vector<std::pair<std::uint32_t, std::uint32_t>> nearest_face_;  // (taken out, face particle)
  // J per metre: the ground taken out, the lining as placed, its hydration.
  double excavated_heat_ = 0.0, lining_heat_ = 0.0, hydration_heat_ = 0.0;
};

// A shaft's sections (each one's `excavation` entry, its name beside it):
// `sections` (the entries, with `name`), and the critical section, the
// smallest margin (or, without a requirement, the thinnest wall after its
// day): `critical_depth`, `critical_section`, `critical_day`, `margin_min`.
nlohmann::json excavation_overview(const std::vector<nlohmann::json>& entries, const std::vector<std::string>& names);

}  // namespace frostwall::freezing
