#include "mechanics/frost_results.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>

#include "geometry/pores.hpp"
#include "pd/pore_expansion.hpp"
#include "io/atomic_file.hpp"
#include "io/polyline_vtk.hpp"
#include "summary/summary.hpp"

namespace frostwall::mechanics {

namespace keys = summary::keys;

using nlohmann::json;
using Vec2 = particles::Vec<2>;

namespace {
json optional_time(const std::optional<double>& t, double unit) { return t ? json(*t / unit) : json(nullptr); }
}  // namespace

CrackMeasure crack_measure(const std::vector<geometry::Polyline>& lines, double area) {
  CrackMeasure c;
  for (const auto& line : lines) {
    const auto& x = line.points;
    for (std::size_t k = 1; k < x.size(); ++k) c.length += (x[k] - x[k - 1]).norm();
    if (line.closed && x.size() > 2) c.length += (x.front() - x.back()).norm();
  }
  c.per_area = area > 0.0 ? c.length / area : 0.0;
  return c;
}

FrostResults::FrostResults(const project::Project& p, const Model& m, const MechanicsRun* mechanics)
    : project_(p),
      rect_(std::get<project::Rectangle>(p.geometry)),
      model_(m),
      mechanics_(mechanics),
      unit_(p.time.unit_seconds()),
      frozen_(rect_.pores.size(), 0.0),
      start_(rect_.pores.size()),
      end_(rect_.pores.size()) {
  if (mechanics_) {
    const auto& P = m.particles();
    mesh_ = std::make_unique<post::IsolineMesh>(std::vector<Vec2>(P.position.begin(), P.position.begin() + P.n_free),
                                                2.5 * P.spacing);
  }
}

FrostResults::~FrostResults() = default;

void FrostResults::after_step(const thermal::ThermalModel& model, double t) {
  frozen_ = geometry::pore_frozen_fraction(model_.pore_of, frozen_.size(), model.liquid_fraction(), model.volume());
  for (std::size_t p = 0; p < frozen_.size(); ++p) {
    if (!start_[p] && frozen_[p] > 0.0) start_[p] = t;
    if (!end_[p] && frozen_[p] >= 1.0) end_[p] = t;
  }
}

DamageState FrostResults::damage_now() const {
  DamageState d;
  if (!mechanics_) return d;
  const auto& solid = mechanics_->solid();
  std::size_t all = 0, broken = 0;
  solid.for_each_bond([&](std::size_t i, std::uint32_t j, const Vec2&, bool intact) {
    if (solid.held(i) || solid.held(j)) return;
    ++all;
    broken += !intact;
  });
  d.broken_bond_share = all > 0 ? double(broken) / double(all) : 0.0;
  d.broken_bond_energy = solid.broken_bond_energy();
  const auto phi = mechanics_->damage();
  const auto& V = model_.particles().volume;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (solid.held(i)) continue;
    d.largest_damage = std::max(d.largest_damage, phi[i]);
    if (phi[i] > crack_damage) d.damaged_area += V[i];
  }
  return d;
}

std::vector<double> FrostResults::rim_damage() const {
  std::vector<double> largest(rect_.pores.size(), 0.0);
  if (!mechanics_) return largest;
  const auto phi = mechanics_->damage();
  const auto& x = model_.particles().position;
  const double horizon = mechanics_->solid().law().horizon;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (model_.pore_of[i] >= 0) continue;
    const auto rim = geometry::nearest_rim(x[i], rect_.pores);
    if (rim.pore >= 0 && rim.distance <= horizon) largest[rim.pore] = std::max(largest[rim.pore], phi[i]);
  }
  return largest;
}

std::vector<double> FrostResults::crack_reach() const {
  std::vector<double> reach(rect_.pores.size(), 0.0);
  if (!mechanics_) return reach;
  const auto phi = mechanics_->damage();
  const auto& x = model_.particles().position;
  for (std::size_t i = 0; i < phi.size(); ++i) {
    if (model_.pore_of[i] >= 0 || phi[i] <= crack_damage) continue;
    const auto rim = geometry::nearest_rim(x[i], rect_.pores);
    if (rim.pore >= 0) reach[rim.pore] = std::max(reach[rim.pore], rim.distance);
  }
  return reach;
}

std::vector<geometry::Polyline> FrostResults::crack_lines() const {
  if (!mechanics_) return {};
  return mesh_->isolines(mechanics_->damage(), crack_damage);
}

std::optional<double> FrostResults::broken_near_rims() const {
  if (!mechanics_) return std::nullopt;
  const auto& x = model_.particles().position;
  std::size_t broken = 0, near = 0;
  mechanics_->solid().for_each_bond([&](std::size_t i, std::uint32_t, const Vec2& xk, bool intact) {
    if (intact) return;
    ++broken;
    const auto rim = geometry::nearest_rim(0.5 * (x[i] + xk), rect_.pores);
    if (rim.pore >= 0 && rim.distance <= rect_.pores[rim.pore].radius) ++near;
  });
  if (broken == 0) return std::nullopt;
  return double(near) / double(broken);
}

void FrostResults::after_equilibrium(double t) {
  const DamageState d = damage_now();
  history_.push_back({t, d.broken_bond_share, d.largest_damage, d.damaged_area, d.broken_bond_energy});
}

void FrostResults::snapshot(double t, const std::filesystem::path& out, const std::string& stem) {
  if (!mechanics_) return;
  const DamageState d = damage_now();
  const auto lines = crack_lines();
  const CrackMeasure c = crack_measure(lines, rect_.width * rect_.height);
  damage_.push_back({{"time", t / unit_},
                     {"broken_bond_share", d.broken_bond_share},
                     {"largest_damage", d.largest_damage},
                     {"damaged_area", d.damaged_area},
                     {"crack_length", c.length},
                     {"crack_length_per_area", c.per_area},
                     {"broken_bond_energy", d.broken_bond_energy}});
  const std::string file = "cracks" + stem.substr(5) + ".vtp";
  io::write_vtp(out / file, lines, io::file_labels(project_));
  cracks_.push_back({{"t", t / unit_}, {"file", file}});
}

void FrostResults::add_fields(io::PointCloudFrame& frame, const thermal::ThermalModel& model) const {
  std::vector<double> id(frame.points.size(), -1.0), material(frame.points.size(), 0.0);
  for (std::size_t i = 0; i < model_.pore_of.size(); ++i)
    if (model_.pore_of[i] >= 0) {
      id[i] = model_.pore_of[i];
      material[i] = model.liquid_fraction()[i] >= 0.5 ? 1.0 : 2.0;
    }
  frame.fields.emplace_back("pore_id", std::move(id));
  frame.fields.emplace_back("material", std::move(material));
}

json FrostResults::finish(const std::filesystem::path& out) const {
  json result;
  const auto rims = rim_damage();
  const auto reach = crack_reach();
  // The ice's volume change (the solid's model, else water's 9 %).
  const auto& expansion = project_.mechanics ? project_.mechanics->freezing_expansion : std::nullopt;
  const double dV = expansion ? expansion->volume_change : project::FreezingExpansion{}.volume_change;
  json pores = json::array();
  for (std::size_t p = 0; p < rect_.pores.size(); ++p) {
    const auto& pore = rect_.pores[p];
    const double S = pore.saturation;
    pores.push_back({{"id", p},
                     {"x", pore.x},
                     {"y", pore.y},
                     {"radius", pore.radius},
                     {"saturation", S},
                     {"imposed_volume_change", pd::pore_excess(dV, S, 1.0)},
                     {"freezing_start", optional_time(start_[p], unit_)},
                     {"freezing_end", optional_time(end_[p], unit_)},
                     {"max_rim_damage", mechanics_ ? json(rims[p]) : json(nullptr)},
                     // any broken bond within a horizon outside its rim
                     {"cracked", mechanics_ ? json(rims[p] > 0.0) : json(nullptr)},
                     {"crack_reach", mechanics_ ? json(reach[p]) : json(nullptr)}});
  }
  result[keys::pores] = pores;
  if (const auto& g = rect_.pore_generator)
    result["pores_generated"] = {{"count", g->count},
                                 {"radius", {g->radius_min, g->radius_max}},
                                 {"min_gap", g->min_gap},
                                 {"seed", g->seed},
                                 {"saturation", {g->saturation_min, g->saturation_max}}};
  std::optional<double> all = 0.0;
  for (const auto& e : end_) all = e && all ? std::optional(std::max(*all, *e)) : std::nullopt;
  result["all_pores_frozen"] = optional_time(all, unit_);
  if (mechanics_) {
    result[keys::damage] = damage_;
    result["cracks"] = cracks_;
    const auto near = broken_near_rims();
    result["broken_bonds_near_rims"] = near ? json(*near) : json(nullptr);
    std::string csv = "time,broken_bond_share,largest_damage,damaged_area,broken_bond_energy\n";
    for (const auto& h : history_)
      csv += fmt::format("{:.6g},{:.6g},{:.6g},{:.6g},{:.6g}\n", h[0] / unit_, h[1], h[2], h[3], h[4]);
    io::write_text_file(out / "damage.csv", csv);
  }
  return result;
}

}  // namespace frostwall::mechanics
