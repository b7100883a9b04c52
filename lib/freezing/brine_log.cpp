#include "freezing/brine_log.hpp"

#include <cmath>
#include <fmt/core.h>

#include "design/annulus_film.hpp"
#include "io/atomic_file.hpp"
#include "project/units.hpp"

namespace frostwall::freezing {

BrineLog::BrineLog(const project::Pipe& pipe, const thermal::ThermalModel& model, std::size_t boundary,
                   std::vector<double> sample_times)
    : pipe_(pipe),
      boundary_(boundary),
      drawn_heat_(model.boundaries()[boundary].film->drawn_heat),
      h_(model.boundaries()[boundary].film->heat_transfer_coefficient),
      perimeter_(model.boundaries()[boundary].film->perimeter),
      sample_times_(std::move(sample_times)) {
  row(model, 0.0, rate_last_);
}

BrineLog::Row BrineLog::row(const thermal::ThermalModel& model, double t, double& section_rate) const {
  const auto& wall = model.wall_temperatures(boundary_);
  // The boundary's own schedule and film: a plant's circuit sets both as it runs.
  const auto& boundary = model.boundaries()[boundary_];
  const double brine = boundary.temperature.at(t), h = boundary.film->heat_transfer_coefficient;
  // Per pipe in the section: its wall is one temperature all round, so a
  // metre of it passes h pi d (T_wall - T_brine), whatever share of it the
  // section holds.
  double in_section = 0.0, wall_sum = 0.0, pipes = 0.0;
  section_rate = 0.0;
  for (std::size_t g = 0; g < perimeter_.size(); ++g) {
    if (perimeter_[g] <= 0.0) continue;
    // Held at the heat drawn: `brine` is that heat per metre of pipe.
    section_rate += drawn_heat_ ? brine * perimeter_[g] / (M_PI * pipe_.diameter)
                                : h * perimeter_[g] * (wall[g] - brine);
    in_section += perimeter_[g];
    wall_sum += perimeter_[g] * wall[g];
    pipes += perimeter_[g] / (M_PI * pipe_.diameter);
  }
  const double wall_mean = in_section > 0.0 ? wall_sum / in_section : brine;
  return {t / project::seconds_per_day, brine, wall_mean, pipes > 0.0 ? section_rate / pipes : 0.0};
}

void BrineLog::after_step(const thermal::ThermalModel& model, double t) {
  double rate = 0.0;
  const Row r = row(model, t, rate);
  h_ = model.boundaries()[boundary_].film->heat_transfer_coefficient;
  extracted_ += 0.5 * (rate + rate_last_) * (t - t_last_);
  t_last_ = t;
  rate_last_ = rate;
  for (; next_ < sample_times_.size() && sample_times_[next_] <= t * (1.0 + 1e-12); ++next_) rows_.push_back(r);
}

nlohmann::json BrineLog::finish(const std::filesystem::path& out) const {
  // Held at the heat drawn there is no brine column, and no film.
  std::string csv = drawn_heat_ ? "day,pipe_wall_C,heat_per_metre_W_per_m\n"
                                : "day,brine_C,pipe_wall_C,heat_per_metre_W_per_m\n";
  nlohmann::json series = nlohmann::json::array();
  for (const auto& r : rows_) {
    csv += drawn_heat_ ? fmt::format("{:.6g},", r.day) : fmt::format("{:.6g},{:.6g},", r.day, r.brine);
    csv += fmt::format("{:.6g},{:.6g}\n", r.wall, r.heat_per_metre);
    series.push_back({r.day, r.wall, r.heat_per_metre});
  }
  io::write_text_file(out / (std::string(summary_key()) + ".csv"), csv);
  nlohmann::json brine = {{"series", series},
                          {"series_columns", {"day", "pipe_wall_C", "heat_per_metre_W_per_m"}},
                          {drawn_heat_ ? "extracted" : "extracted_by_film", extracted_},
                          {"unit", "J/m of the simulated section"}};
  if (drawn_heat_) return brine;
  brine["heat_transfer_coefficient"] = h_;
  if (pipe_.annulus) {
    const auto film = design::annulus_film(*pipe_.annulus, pipe_.diameter);
    brine["annulus"] = {{"reynolds", film.reynolds},
                        {"prandtl", film.prandtl},
                        {"nusselt", film.nusselt},
                        {"regime", std::string(design::name(film.regime))},
                        {"h_inner_wall", film.h_inner}};
  }
  return brine;
}

}  // namespace frostwall::freezing
