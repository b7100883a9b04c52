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
#include <limits>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

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
  // The longest next step: a fifth of the hydration's release time while
  // the lining sets (none otherwise).
  double step_limit(double t) const;

  bool dug() const { return dug_; }
  double day() const;          // the section's excavation day
  double face_radius() const;  // m: the ground's face (the excavation radius)
  // Per particle: no longer ground (taken out, or the lining since).
  const std::vector<char>& not_ground() const { return not_ground_; }
  // Heat the excavation moved, J per metre: the ground taken out (leaving),
  // the lining as placed and its hydration (entering).
  double excavated_heat() const { return excavated_heat_; }
  double lining_heat() const { return lining_heat_; }
  double hydration_heat() const { return hydration_heat_; }
  // The summary's facts of the section's excavation (depth, days, particles).
  nlohmann::json facts() const;

 private:
  void dig(double t);
  void line(double t);
  // Joins the particles of `side` near radius a to the face, the rest of the
  // face's pairs cut; the face's film then over that circle.
  void join_face(double a, const std::vector<char>& side);
  void stability_changed();

  const project::Project& p_;
  const project::Excavation& e_;
  Model& m_;
  double radius_ = 0.0;  // the excavation radius
  double share_ = 1.0;   // the part of the circle in the section
  int face_ = -1;        // the face's boundary
  std::uint32_t node_ = 0;
  bool dug_ = false, lined_ = false;
  double lined_at_ = 0.0, released_ = 0.0;
  std::vector<std::uint32_t> taken_, lining_;
  std::vector<char> not_ground_;
  std::size_t face_particles_ = 0;
  double excavated_heat_ = 0.0, lining_heat_ = 0.0, hydration_heat_ = 0.0;
};

}  // namespace frostwall::freezing
