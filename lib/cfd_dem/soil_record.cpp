#include <cmath>
#include <fmt/format.h>

#include "dem/packing.hpp"
#include "pore_water/bed_resistance.hpp"
#include "cfd_dem/soil.hpp"

namespace frostwall::cfd_dem {

using nlohmann::json;

namespace {
json optional(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }
json vec(const std::array<double, 3>& f) { return json::array({f[0], f[1], f[2]}); }
json maybe(const std::optional<double>& v) { return v ? json(*v) : json(nullptr); }

json flank(const std::optional<post::Flank>& f) {
  if (!f) return nullptr;
  return {{"slope_deg", f->slope_deg}, {"x_10_percent_m", f->x10}, {"x_90_percent_m", f->x90}, {"foot_m", f->foot}};
}

json bump(const post::Bump& b, const char* peak_name) {
  return {{peak_name, b.peak},
          {"at_m", b.peak_x},
          {"base_m", b.base},
          {"width_m", maybe(b.width())},
          {"slope_deg", maybe(b.mean_slope_deg())},
          {"low_side", flank(b.low_side)},
          {"high_side", flank(b.high_side)}};
}
}  // namespace

// The crater from the settlement along x through the cavity: depth, width
// between the flanks' feet at the original surface, slope (the mean of the
// two flanks between 10 % and 90 % of the depth), each flank, the volume.
json crater_json(const Crater& c) {
  json out = bump(c.along_x, "depth_m");
  out["volume_m3"] = c.volume;
  return out;
}

json heap_json(const Heap& h) {
  return {{"angle_of_repose_deg", maybe(h.angle_deg())},
          {"along_x", bump(h.along_x, "height_m")},
          {"along_y", bump(h.along_y, "height_m")}};
}

json packing_regime(const project::CfdDem& c, double grain_volume) {
  double volume = 1.0;
  for (int k = 0; k < 3; ++k) volume *= c.box.high[k] - c.box.low[k];
  if (c.cavity) volume -= 4.0 / 3.0 * M_PI * std::pow(c.cavity->radius, 3);
  const double n = 1.0 - grain_volume / volume;
  const double rho_f = c.fluid.density, rho_p = c.grains.density;
  const double g = std::hypot(c.gravity[0], c.gravity[1], c.gravity[2]);
  const pore_water::Fluid fluid{rho_f, c.fluid.viscosity};
  const double d = dem::mean_grain_diameter(c.grains);
  const double weight = (1.0 - n) * (rho_p - rho_f) * g;  // buoyant, per volume
  const double u_mf = pore_water::ergun_velocity(fluid, n, d, weight);
  json out = {{"porosity", n},
              {"critical_gradient", (rho_p / rho_f - 1.0) * (1.0 - n)},
              {"minimum_fluidisation_velocity_m_s", u_mf}};
  if (c.flow && !c.flow->darcy_velocity.empty()) {
    double u = 0.0;
    for (const auto& [t, v] : c.flow->darcy_velocity) u = std::max(u, std::abs(v));
    const double gradient = pore_water::ergun_gradient(fluid, n, d, u) / (rho_f * g);
    out["darcy_velocity_m_s"] = u;
    out["hydraulic_gradient"] = gradient;
    out["above_fluidisation"] = u > u_mf;
    out["note"] =
        u > u_mf
            ? fmt::format("{:.3g} m/s is {:.1f} times Ergun's minimum fluidisation velocity of this packing: the "
                          "seepage gradient ({:.2f}) exceeds the critical gradient ({:.2f}), so the ground at the "
                          "inflow face is loosened and boils rather than seeping",
                          u, u / (u_mf), gradient, (rho_p / rho_f - 1.0) * (1.0 - n))
            : fmt::format("{:.3g} m/s is below Ergun's minimum fluidisation velocity of this packing ({:.3g} m/s): "
                          "seepage gradient {:.3f} against the critical {:.2f}",
                          u, u_mf, gradient, (rho_p / rho_f - 1.0) * (1.0 - n));
  }
  return out;
}

void SoilRecord::add(SoilRow row, bool snapshot) {
  rows_.push_back(std::move(row));
  if (snapshot) snapshots_.push_back(rows_.size() - 1);
}

// The loss rate of an interval: the grains that left the soil in it (into
// the cavity or out through the outflow face) over those in the soil at
// its start; the change in contacts likewise between outputs.
json SoilRecord::summary(const json& regime, const std::vector<double>& bins,
                         const std::vector<double>& initial) const {
  json series = json::array();
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const auto& r = rows_[k];
    json row = {{"time", r.time},
                {"grains_in_soil", r.grains},
                {"lost_to_cavity", r.lost_cavity},
                {"washed_out", r.lost_outflow},
                {"contacts", r.contacts},
                {"zone_porosity", optional(r.measures.zone_porosity)},
                {"pressure_drop_to_a_Pa", optional(r.measures.pressure_drop_a)},
                {"grains_at_a", r.measures.grains_a},
                {"mean_drag_at_a_N", vec(r.measures.mean_force_a[0])},
                {"mean_pressure_gradient_force_at_a_N", vec(r.measures.mean_force_a[1])},
                {"mean_buoyancy_at_a_N", vec(r.measures.mean_force_a[2])},
                {"settlement_max_m", r.measures.settlement_max},
                {"settlement_width_m", r.measures.settlement_width},
                {"displaced_grains", r.measures.displaced},
                {"moved_one_diameter", r.measures.moved},
                {"cone_angle_deg", r.measures.cone_angle ? json(*r.measures.cone_angle) : json(nullptr)},
                {"slip_surface_angle_deg", maybe(r.measures.slip_angle)},
                {"grains_in_cavity", r.in_cavity},
                {"grains_in_model", r.in_model}};
    if (r.measures.crater) {
      const auto& cr = *r.measures.crater;
      row["crater_depth_m"] = cr.along_x.peak;
      row["crater_width_m"] = maybe(cr.along_x.width());
      row["crater_slope_deg"] = maybe(cr.along_x.mean_slope_deg());
      row["crater_volume_m3"] = cr.volume;
    }
    if (r.measures.heap) row["angle_of_repose_deg"] = maybe(r.measures.heap->angle_deg());
    if (k > 0) {
      const auto& p = rows_[k - 1];
      const double left = (r.lost_cavity - p.lost_cavity) + (r.lost_outflow - p.lost_outflow);
      row["loss_rate"] = p.grains > 0 ? left / p.grains : 0.0;
      row["loss_rate_cavity"] = p.grains > 0 ? (r.lost_cavity - p.lost_cavity) / p.grains : 0.0;
      row["loss_rate_outflow"] = p.grains > 0 ? (r.lost_outflow - p.lost_outflow) / p.grains : 0.0;
      row["contact_change"] = r.contacts - p.contacts;
    }
    series.push_back(row);
  }
  json profiles = json::array();
  for (std::size_t k : snapshots_) {
    const auto& r = rows_[k];
    json settlement = json::array();
    for (std::size_t b = 0; b < bins.size() && b < r.measures.surface.size(); ++b)
      settlement.push_back({bins[b], initial[b] - r.measures.surface[b]});
    profiles.push_back({{"time", r.time},
                        {"settlement", settlement},
                        {"settlement_max_m", r.measures.settlement_max},
                        {"settlement_width_m", r.measures.settlement_width},
                        {"displaced_grains", r.measures.displaced},
                        {"cone_angle_deg", r.measures.cone_angle ? json(*r.measures.cone_angle) : json(nullptr)},
                        {"slip_surface_angle_deg", maybe(r.measures.slip_angle)}});
    if (r.measures.crater) profiles.back()["crater"] = crater_json(*r.measures.crater);
    if (r.measures.heap) profiles.back()["heap"] = heap_json(*r.measures.heap);
  }
  json out = {{"series", series}, {"surface_profiles", profiles}, {"regime", regime}};
  if (!rows_.empty()) {
    const auto &first = rows_.front(), &last = rows_.back();
    out["grains_at_start"] = first.grains + first.lost_cavity + first.lost_outflow;
    out["lost_to_cavity"] = last.lost_cavity;
    out["washed_out"] = last.lost_outflow;
    out["grains_in_soil_at_end"] = last.grains;
    out["grains_in_cavity_at_end"] = last.in_cavity;
    out["slip_surface_angle_deg"] = maybe(last.measures.slip_angle);
    if (last.measures.crater) out["crater"] = crater_json(*last.measures.crater);
    if (last.measures.heap) out["heap"] = heap_json(*last.measures.heap);
  }
  if (c_.point_a) out["point_a"] = {c_.point_a->at(0), c_.point_a->at(1), c_.point_a->at(2)};
  return out;
}

std::string SoilRecord::csv() const {
  std::string text =
      "time_s,grains_in_soil,lost_to_cavity,washed_out,contacts,zone_porosity,pressure_drop_to_a_Pa,grains_at_a,"
      "drag_at_a_N,pressure_gradient_force_at_a_N,buoyancy_at_a_N,settlement_max_m,settlement_width_m,displaced_grains,"
      "cone_angle_deg,grains_in_cavity,grains_in_model,slip_surface_angle_deg,crater_depth_m,crater_slope_deg\n";
  // Forces at A: their magnitudes.
  auto norm = [](const std::array<double, 3>& f) { return std::hypot(f[0], f[1], f[2]); };
  for (const auto& r : rows_) {
    const auto& m = r.measures;
    auto opt = [](const std::optional<double>& v) { return v ? fmt::format("{:.6g}", *v) : std::string(); };
    text += fmt::format("{:.9g},{},{},{},{},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{},{},{},{},{},{},{}\n",
                        r.time, r.grains, r.lost_cavity, r.lost_outflow, r.contacts, m.zone_porosity, m.pressure_drop_a,
                        m.grains_a, norm(m.mean_force_a[0]), norm(m.mean_force_a[1]), norm(m.mean_force_a[2]),
                        m.settlement_max, m.settlement_width, m.displaced, opt(m.cone_angle), r.in_cavity, r.in_model,
                        opt(m.slip_angle), m.crater ? fmt::format("{:.6g}", m.crater->along_x.peak) : std::string(),
                        m.crater ? opt(m.crater->along_x.mean_slope_deg()) : std::string());
  }
  return text;
}

}  // namespace frostwall::cfd_dem
