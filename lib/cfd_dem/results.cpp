#include "cfd_dem/results.hpp"

#include <cmath>
#include <fmt/format.h>

#include "dem/packing.hpp"
#include "pore_water/bed_resistance.hpp"
#include "summary/summary.hpp"

namespace frostwall::cfd_dem {

using nlohmann::json;

namespace {
// Bed expansion that counts as lift-off: 0.5 % of the bed's length, far
// above the elastic rebound of the contacts as the load comes off them.
constexpr double lift_expansion = 0.005;
constexpr std::size_t plateau_samples = 10;
}  // namespace

CfdDemResults::CfdDemResults(const project::Project& p) : p_(p), c_(*p.cfd_dem) {
  if (c_.flow) {
    axis_ = static_cast<int>(c_.flow->inflow) / 2;
    from_low_ = static_cast<int>(c_.flow->inflow) % 2 == 0;
  } else {
    axis_ = std::max(0, project::gravity_axis(c_));
    from_low_ = c_.gravity[axis_] <= 0.0;
  }
  area_ = 1.0;
  for (int k = 0; k < 3; ++k)
    if (k != axis_) area_ *= c_.box.high[k] - c_.box.low[k];
}

CfdDemSample CfdDemResults::sample(double t, double u, const GrainTotals& g, const pore_water::FluidGrid& grid,
                                   const pore_water::SolveReport& report) const {
  CfdDemSample s;
  s.time = t;
  s.inflow_velocity = u;
  s.grains = g.count - g.in_cavity;
  s.in_cavity = g.in_cavity;
  s.contacts = g.contacts;
  if (g.volume > 0.0) {
    const double mean = g.position_sum[axis_] / g.volume;
    s.bed_length = 2.0 * (from_low_ ? mean - c_.box.low[axis_] : c_.box.high[axis_] - mean);
    s.porosity = 1.0 - g.volume / (area_ * s.bed_length);
    const double gn = std::hypot(c_.gravity[0], c_.gravity[1], c_.gravity[2]);
    if (gn > 0.0)
      for (int k = 0; k < 3; ++k) s.settling_velocity += g.velocity_sum[k] / g.volume * c_.gravity[k] / gn;
  }
  for (int kind = 0; kind < 3; ++kind)
    for (int k = 0; k < 3; ++k) s.mean_force[kind][k] = g.count > 0 ? g.force[kind][k] / g.count : 0.0;
  if (c_.flow)
    s.pressure_drop = grid.face_pressure(static_cast<int>(c_.flow->inflow)) -
                      grid.face_pressure(static_cast<int>(c_.flow->outflow));
  s.inflow = grid.inflow();
  s.outflow = grid.outflow();
  s.imbalance = grid.largest_cell_imbalance();
  s.picard_iterations = report.picard_iterations;
  return s;
}

void CfdDemResults::add(const CfdDemSample& s, bool snapshot) {
  series_.push_back(s);
  if (snapshot) snapshots_.push_back(series_.size() - 1);
}

// Minimum fluidisation of a free bed under a rising upward flow, and its
// lift-off (the first sample whose bed is longer than at the start by
// lift_expansion). Beside them, what
// the formulas say for the bed as it started: the buoyant weight per area,
// Ergun's minimum fluidisation velocity (where its pressure drop carries
// that weight), Terzaghi's critical gradient i_c = (G_s - 1)(1 - n).
json CfdDemResults::fluidisation() const {
  if (!c_.flow || c_.grains.held || series_.empty() || c_.flow->inflow_pressure) return nullptr;
  // Only an upward flow lifts a bed: the flow along gravity's axis, in
  // against it.
  if (std::abs(c_.gravity[axis_]) < 0.5 * std::hypot(c_.gravity[0], c_.gravity[1], c_.gravity[2]) ||
      (from_low_ ? c_.gravity[axis_] > 0.0 : c_.gravity[axis_] < 0.0))
    return nullptr;
  const auto& start = series_.front();
  const double g = std::abs(c_.gravity[axis_]);
  const double rho_f = c_.fluid.density, rho_p = c_.grains.density;
  const double solid = (1.0 - start.porosity) * start.bed_length;  // grain volume per area
  const double weight = (rho_p - rho_f) * g * solid;               // buoyant, Pa
  const pore_water::Fluid fluid{rho_f, c_.fluid.viscosity};
  const double ergun_velocity =
      pore_water::ergun_velocity(fluid, start.porosity, dem::mean_grain_diameter(c_.grains), weight / start.bed_length);
  json out = {{"bed_length_m", start.bed_length},
              {"porosity", start.porosity},
              {"buoyant_weight_Pa", weight},
              {"ergun_velocity_m_s", ergun_velocity},
              {"critical_gradient", (rho_p / rho_f - 1.0) * (1.0 - start.porosity)},
              {"lift_expansion", lift_expansion}};
  // Lift-off: the bed grows by lift_expansion.
  std::size_t lift = series_.size();
  for (std::size_t k = 0; k < series_.size(); ++k)
    if (series_[k].bed_length > (1.0 + lift_expansion) * start.bed_length) {
      lift = k;
      break;
    }
  if (lift == series_.size()) {
    out["velocity_m_s"] = nullptr;  // the bed never lifted
    return out;
  }
  out["lift_velocity_m_s"] = series_[lift].inflow_velocity;
  out["lift_time_s"] = series_[lift].time;
  // Kunii & Levenspiel's reading of the pressure-drop curve: the plateau
  // the lifted bed holds (its mean pressure drop after lift-off) meets
  // the fixed bed's branch dP = a U + b U^2 (least squares over the samples
  // before lift-off below 0.9 of the plateau).
  // The plateau is read just past lift-off (the next plateau_samples):
  // far beyond it the coarse grid's bed surface smears more as the bed
  // expands, and its pressure drop creeps up.
  const std::size_t end = std::min(series_.size(), lift + plateau_samples);
  double plateau = 0.0;
  for (std::size_t k = lift; k < end; ++k) plateau += series_[k].pressure_drop;
  plateau /= static_cast<double>(end - lift);
  double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
  for (std::size_t k = 0; k < lift; ++k) {
    const double U = series_[k].inflow_velocity, dP = series_[k].pressure_drop;
    if (U <= 0.0 || dP >= 0.9 * plateau) continue;
    s11 += U * U, s12 += U * U * U, s22 += U * U * U * U, r1 += U * dP, r2 += U * U * dP;
  }
  const double det = s11 * s22 - s12 * s12;
  out["plateau_pressure_drop_Pa"] = plateau;
  if (det > 0.0) {
    const double a = (r1 * s22 - r2 * s12) / det, b = (s11 * r2 - s12 * r1) / det;
    const double U = b != 0.0 ? (-a + std::sqrt(a * a + 4.0 * b * plateau)) / (2.0 * b) : plateau / a;
    out["velocity_m_s"] = U;
    out["gradient"] = plateau / (rho_f * g * start.bed_length);
  } else {
    out["velocity_m_s"] = nullptr;  // no fixed-bed samples to fit
  }
  return out;
}

json CfdDemResults::summary(const json& facts) const {
  json j = facts;
  j[summary::keys::project] = p_.name;
  j[summary::keys::frostwall_version] = FROSTWALL_VERSION;
  j[summary::keys::physics] = "cfd-dem";
  j["bed_axis"] = std::string(1, "xyz"[axis_]);
  json settling = json::array(), snapshots = json::array(), ergun = json::array();
  for (const auto& s : series_) settling.push_back({s.time, s.settling_velocity});
  auto force = [](const std::array<double, 3>& f) { return json::array({f[0], f[1], f[2]}); };
  for (std::size_t k : snapshots_) {
    const auto& s = series_[k];
    std::array<double, 3> total{};
    for (int kind = 0; kind < 3; ++kind)
      for (int a = 0; a < 3; ++a) total[a] += s.mean_force[kind][a];
    snapshots.push_back({{"time", s.time},
                         {"grains_in_soil", s.grains},
                         {"grains_in_cavity", s.in_cavity},
                         {"porosity", s.porosity},
                         {"bed_length_m", s.bed_length},
                         {"contacts", s.contacts},
                         {"mean_fluid_force_N", force(total)},
                         {"mean_drag_N", force(s.mean_force[0])},
                         {"mean_pressure_gradient_force_N", force(s.mean_force[1])},
                         {"mean_buoyancy_N", force(s.mean_force[2])},
                         {"pressure_drop_Pa", s.pressure_drop}});
    if (c_.flow) {
      // The fluid's total force on the grains along the bed, drag plus
      // pressure gradient (buoyancy is the hydrostatic part, not the flow's).
      const double sign = from_low_ ? 1.0 : -1.0;
      const double on_grains = sign * (s.grains + s.in_cavity) * (s.mean_force[0][axis_] + s.mean_force[1][axis_]);
      ergun.push_back({{"time", s.time},
                       {"superficial_velocity", s.inflow_velocity},
                       {"porosity", s.porosity},
                       {"bed_length", s.bed_length},
                       {"pressure_drop_Pa", s.pressure_drop},
                       {"fluid_force_on_grains_N", on_grains},
                       {"pressure_drop_times_area_N", s.pressure_drop * area_}});
    }
  }
  j["settling"] = settling;
  if (!series_.empty()) {  // the bed as the run starts (after settling)
    const auto& s0 = series_.front();
    j["series_start"] = {{"bed_length_m", s0.bed_length},
                         {"porosity", s0.porosity},
                         {"contacts", s0.contacts},
                         {"grains_in_soil", s0.grains}};
  }
  if (!series_.empty() && series_.back().grains + series_.back().in_cavity == 1.0)
    j["terminal_velocity_m_s"] = series_.back().settling_velocity;
  j["snapshots"] = snapshots;
  if (c_.flow) j["ergun"] = ergun;
  if (const json f = fluidisation(); !f.is_null()) j["minimum_fluidisation"] = f;
  double imbalance = 0.0, flow = 0.0, mismatch = 0.0;
  for (const auto& s : series_) {
    imbalance = std::max(imbalance, s.imbalance);
    flow = std::max(flow, std::abs(s.inflow));
    mismatch = std::max(mismatch, std::abs(s.inflow - s.outflow));
  }
  j["mass_balance"] = {{"largest_cell_imbalance_m3_s", imbalance},
                       {"largest_inflow_m3_s", flow},
                       {"largest_inflow_minus_outflow_m3_s", mismatch}};
  return j;
}

std::string CfdDemResults::csv() const {
  std::string text =
      "time_s,inflow_velocity_m_s,grains,bed_length_m,porosity,contacts,pressure_drop_Pa,settling_velocity_m_s,"
      "mean_drag_N,mean_pressure_gradient_force_N,mean_buoyancy_N,inflow_m3_s,outflow_m3_s,picard_iterations\n";
  for (const auto& s : series_)
    text += fmt::format("{:.9g},{:.9g},{},{:.9g},{:.9g},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{}\n",
                        s.time, s.inflow_velocity, s.grains, s.bed_length, s.porosity, s.contacts, s.pressure_drop,
                        s.settling_velocity, s.mean_force[0][axis_], s.mean_force[1][axis_], s.mean_force[2][axis_],
                        s.inflow, s.outflow, s.picard_iterations);
  return text;
}

}  // namespace frostwall::cfd_dem
