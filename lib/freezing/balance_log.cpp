#include "freezing/balance_log.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "io/atomic_file.hpp"

namespace frostwall::freezing {

namespace {
double coldest(const thermal::ThermalModel& model) {
  const auto& T = model.temperature();
  return *std::min_element(T.begin(), T.begin() + static_cast<long>(model.free_count()));
}
}  // namespace

BalanceLog::BalanceLog(const thermal::ThermalModel& model, double porosity, double time_unit_seconds)
    : porosity_(porosity), unit_(time_unit_seconds) {
  sample(model, 0.0);
  last_min_ = rows_.front().min_temperature;
}

void BalanceLog::after_step(const thermal::ThermalModel& model, double t) {
  const double Tf = model.law().freezing_point();
  const double now = coldest(model);
  if (!thaw_time_ && last_min_ < Tf && now >= Tf) {  // between the two steps
    const double w = (Tf - last_min_) / (now - last_min_);
    thaw_time_ = (last_t_ + w * (t - last_t_)) / unit_;
  }
  last_t_ = t;
  last_min_ = now;
}

void BalanceLog::sample(const thermal::ThermalModel& model, double t) {
  double water = 0.0;
  for (std::size_t i = 0; i < model.free_count(); ++i) water += model.volume()[i] * model.liquid_fraction()[i];
  rows_.push_back({t, coldest(model), porosity_ * water, model.stored_heat()});
}

nlohmann::json BalanceLog::finish(const std::filesystem::path& out) const {
  nlohmann::json rows = nlohmann::json::array();
  std::string csv = "time,min_temperature_C,liquid_water_m3_per_m,net_heat_out_W_per_m\n";
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const Row& r = rows_[k];
    // The heat lost since the sample before (from the next one for the first).
    const std::size_t a = k == 0 ? 0 : k - 1, b = k == 0 ? std::min<std::size_t>(1, rows_.size() - 1) : k;
    const double dt = rows_[b].t - rows_[a].t;
    const double out_W = dt > 0.0 ? -(rows_[b].stored_heat - rows_[a].stored_heat) / dt : 0.0;
    nlohmann::json row = {{"time", r.t / unit_}, {"min_temperature", r.min_temperature}, {"net_heat_out_W", out_W}};
    row["liquid_water_m3"] = porosity_ > 0.0 ? nlohmann::json(r.liquid_water) : nlohmann::json(nullptr);
    rows.push_back(row);
    csv += fmt::format("{:.8g},{:.8g},{},{:.8g}\n", r.t / unit_, r.min_temperature,
                       porosity_ > 0.0 ? fmt::format("{:.8g}", r.liquid_water) : std::string(), out_W);
  }
  io::write_text_file(out / "balance.csv", csv);
  return rows;
}

}  // namespace frostwall::freezing
