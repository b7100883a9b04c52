#include "freezing/excavation_run.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "freezing/excavation_face.hpp"
#include "io/atomic_file.hpp"
#include "project/units.hpp"
#include "thermal/super_time_stepping.hpp"

namespace frostwall::freezing {

namespace {
// The lining's material: no latent heat, one conductivity and heat
// capacity; its enthalpy counted from the ground's freezing point (the
// ground's own datum), so the heat balance's entries read alike.
thermal::PhaseChangeLaw lining_law(const project::Lining& l, double freezing_point) {
  project::Soil s;
  s.name = "lining";
  s.density = l.density;
  s.unfrozen.conductivity = {l.conductivity, l.conductivity};
  s.frozen.conductivity = {l.conductivity, l.conductivity};
  s.unfrozen.heat_capacity = l.heat_capacity;
  s.frozen.heat_capacity = l.heat_capacity;
  s.latent_heat = 0.0;
  s.freezing_point = freezing_point;
  return thermal::PhaseChangeLaw(s);
}
}  // namespace

ExcavationRun::ExcavationRun(const project::Project& p, Model& m)
    : p_(p),
      e_(*p.excavation),
      m_(m),
      radius_(*std::get<project::ShaftSection>(p.geometry).shaft.excavation_radius),
      share_(m.shaft->wedge.angle / (2.0 * std::numbers::pi)),
      face_boundary_(face_boundary(*m.scene)),
      node_(face_particle(*m.scene)) {}

double ExcavationRun::day() const { return e_.day(); }
double ExcavationRun::face_radius() const { return radius_; }

double ExcavationRun::next_event() const {
  if (!dug_) return day() * project::seconds_per_day;
  if (e_.lining && !lined_) return day() * project::seconds_per_day + e_.lining->placed_after;
  return std::numeric_limits<double>::infinity();
}

void ExcavationRun::apply(double t) {
  if (!dug_) dig(t);
  if (dug_ && e_.lining && !lined_ && t >= next_event() * (1.0 - 1e-12)) line(t);
}

void ExcavationRun::dig(double t) {
  auto& model = *m_.model;
  const auto& P = m_.particles();
  std::vector<char> ground(model.free_count(), 1);
  for (std::uint32_t i = 0; i < model.free_count(); ++i)
    if (P.position[i].norm() < radius_) {
      taken_.push_back(i);
      ground[i] = 0;
      excavated_heat_ += model.volume()[i] * model.enthalpy()[i];
    }
  model.remove_particles(taken_);
  const auto face = join_face(radius_, ground);
  // Each particle taken out reads as the face particle nearest its
  // direction when the wall is measured.
  for (const std::uint32_t i : taken_) {
    const particles::Vec<2> on_face = P.position[i].normalized() * radius_;
    std::uint32_t best = face.front().particle;
    for (const auto& j : face)
      if ((P.position[j.particle] - on_face).squaredNorm() < (P.position[best] - on_face).squaredNorm())
        best = j.particle;
    nearest_face_.emplace_back(i, best);
  }
  model.set_boundary_temperature(face_boundary_, e_.air_temperature);
  dug_ = true;
  after_step(t);
}

void ExcavationRun::line(double t) {
  auto& model = *m_.model;
  const auto& l = *e_.lining;
  const double inner = radius_ - l.thickness;
  const auto& P = m_.particles();
  for (const std::uint32_t i : taken_)
    if (P.position[i].norm() >= inner) lining_.push_back(i);
  const std::uint8_t material = model.add_material(lining_law(l, p_.soil.freezing_point));
  const double placed = l.placement_temperature.value_or(e_.air_temperature.at(t));
  model.restore_particles(lining_, material, placed);
  std::vector<char> side(model.free_count(), 0);
  for (const std::uint32_t i : lining_) {
    side[i] = 1;
    lining_heat_ += model.volume()[i] * model.enthalpy()[i];
  }
  join_face(inner, side);
  lined_ = true;
  lined_at_ = now_ = t;
}

std::vector<FaceWeight> ExcavationRun::join_face(double a, const std::vector<char>& side) {
  auto& model = *m_.model;
  for (const auto& w : face_) model.set_pair_weight(w.pair, 0.0);  // the face as it stood
  face_ = face_weights(model.pairs(), m_.particles(), node_, a, share_, side);
  for (const auto& w : face_) model.set_pair_weight(w.pair, w.weight);
  model.set_film_perimeter(static_cast<std::size_t>(face_boundary_), 0, 2.0 * std::numbers::pi * a * share_);
  stability_changed();
  return face_;
}

void ExcavationRun::stability_changed() {
  if (auto* rkl2 = thermal::find_integrator<thermal::SuperTimeStepping>(m_.integrator.get()))
    rkl2->forget_stability_limit();
}

void ExcavationRun::after_step(double t) {
  now_ = t;
  if (!dug_) return;
  auto& model = *m_.model;
  if (lined_) {
    const double released = e_.lining->hydration.at(t - lined_at_);
    if (const double dq = released - released_; dq > 0.0) {
      const double per_volume = e_.lining->density * dq;
      for (const std::uint32_t i : lining_) {
        model.set_enthalpy(i, model.enthalpy()[i] + per_volume);
        hydration_heat_ += model.volume()[i] * per_volume;
      }
      released_ = released;
    }
  }
  // The ground taken out (not the lining) at the face's temperature.
  const double shown = model.law().enthalpy(model.temperature()[node_]);
  for (const std::uint32_t i : taken_)
    if (model.removed(i)) model.set_enthalpy(i, shown);
}

void ExcavationRun::as_ground(std::vector<double>& liquid_fraction) const {
  for (const auto& [i, face] : nearest_face_) liquid_fraction[i] = liquid_fraction[face];
}

void ExcavationRun::as_shown(std::vector<double>& liquid_fraction) const {
  for (const std::uint32_t i : taken_) liquid_fraction[i] = 1.0;
}

double ExcavationRun::step_limit() const {
  if (!lined_) return std::numeric_limits<double>::infinity();
  const auto& q = e_.lining->hydration;
  if (now_ - lined_at_ >= q.end_time()) return std::numeric_limits<double>::infinity();
  const double release = q.released.points.empty()
                             ? q.release_time
                             : q.end_time() / std::max<std::size_t>(q.released.points.size() - 1, 4);
  return std::max(0.2 * release, 60.0);
}

void ExcavationRun::add_heat(nlohmann::json& from_boundaries) const {
  from_boundaries.update(
      {{"excavated", -excavated_heat_}, {"lining_placed", lining_heat_}, {"hydration", hydration_heat_}});
}

nlohmann::json ExcavationRun::summary(const nlohmann::json& wall_after, const std::filesystem::path& out) const {
  nlohmann::json entry = facts();
  entry.update(wall_after);
  // The series as a table; an empty cell where a value is null.
  std::string csv = "day,days_after,thickness_m,mean_temperature_C,required_thickness_m,margin_m\n";
  auto cell = [](const nlohmann::json& v) { return v.is_number() ? fmt::format("{:.6g}", v.get<double>()) : ""; };
  for (const auto& r : entry["series"])
    csv += fmt::format("{},{},{},{},{},{}\n", cell(r["day"]), cell(r["days_after"]), cell(r["thickness"]),
                       cell(r["mean_temperature"]), cell(r["required_thickness"]), cell(r["margin"]));
  io::write_text_file(out / "excavation.csv", csv);
  nlohmann::json section = entry;
  section.erase("series");
  entry.update(excavation_overview({section}, {p_.name}));  // the shaft's one section, critical
  return entry;
}

nlohmann::json excavation_overview(const std::vector<nlohmann::json>& entries, const std::vector<std::string>& names) {
  using nlohmann::json;
  json sections = json::array();
  std::optional<std::size_t> critical;
  // Ranked by the smallest margin; sections without one by the thinnest wall.
  auto key = [&](std::size_t k) {
    const json& e = sections[k];
    return e["margin_min"].is_number()       ? std::make_pair(0, e["margin_min"].get<double>())
           : e["thinnest_after"].is_number() ? std::make_pair(1, e["thinnest_after"].get<double>())
                                             : std::make_pair(2, 0.0);
  };
  for (std::size_t k = 0; k < entries.size(); ++k) {
    json entry = entries[k];
    for (const char* field : {"sections", "critical_depth", "critical_section", "critical_day"}) entry.erase(field);
    entry["name"] = names[k];
    sections.push_back(entry);
    if (key(k).first < 2 && (!critical || key(k) < key(*critical))) critical = k;
  }
  json overview = {{"sections", sections}};
  if (!critical) {
    overview["critical_depth"] = nullptr;
    return overview;
  }
  const json& c = sections[*critical];
  overview["critical_depth"] = c["depth"];
  overview["critical_section"] = c["name"];
  overview["critical_day"] = c["margin_min"].is_number() ? c["margin_min_day"] : c["thinnest_after_day"];
  overview["margin_min"] = c["margin_min"];
  return overview;
}

nlohmann::json ExcavationRun::facts() const {
  nlohmann::json f = {{"depth", e_.depth},
                      {"day", day()},
                      {"face_radius", radius_},
                      {"particles_taken_out", taken_.size()},
                      {"face_particles", face_.size()}};
  if (e_.lining) {
    f["lining_day"] = day() + e_.lining->placed_after / project::seconds_per_day;
    f["lining_inner_radius"] = radius_ - e_.lining->thickness;
    f["lining_particles"] = lining_.size();
  }
  return f;
}

}  // namespace frostwall::freezing
