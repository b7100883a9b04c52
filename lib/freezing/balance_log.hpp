// The domain's balance over a plain-geometry run, InterFrost's performance
// measures per metre of thickness: PM1 the coldest temperature of the
// ground (and when it first rises above the freezing point), PM2 the net
// heat leaving through the faces, PM3 the liquid water held. The heat out
// between two samples is the heat the domain lost over the interval: what
// crossed its faces by conduction and with the water, to the energy
// balance's round-off. balance.csv and the summary's "balance" and
// "thaw_time".
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "thermal/thermal_model.hpp"

namespace frostwall::freezing {

class BalanceLog {
 public:
  // porosity: the ground's, for the liquid water (0: not known, none
  // written). The first row is the model's state at t = 0.
  BalanceLog(const thermal::ThermalModel& model, double porosity, double time_unit_seconds);
  // Every step: the coldest temperature's crossing of the freezing point.
  void after_step(const thermal::ThermalModel& model, double t);
  // At the regular output times: one row.
  void sample(const thermal::ThermalModel& model, double t);
  // The summary's "balance" rows; writes balance.csv.
  nlohmann::json finish(const std::filesystem::path& out) const;
  // When the coldest ground first rose above the freezing point after
  // being below it (project time unit); nullopt if it never did.
  std::optional<double> thaw_time() const { return thaw_time_; }

 private:
  struct Row {
    double t, min_temperature, liquid_water, stored_heat;
  };
  double porosity_, unit_;
  std::vector<Row> rows_;
  double last_t_ = 0.0, last_min_ = 0.0;  // the last step's time and coldest temperature
  std::optional<double> thaw_time_;
};

}  // namespace frostwall::freezing
