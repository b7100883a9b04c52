#include "calibrate/forward.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "freezing/heat_run.hpp"
#include "freezing/plant_run.hpp"
#include "particles/side_by_side.hpp"

namespace frostwall::calibrate {

namespace fs = std::filesystem;
using project::Reading;

namespace {

// Reads the run's sensors (freezing::Thermometers, linear in time between
// the two steps around each reading) at the readings' times, and ends the
// run after the last.
class SensorRecorder : public freezing::RunExtension {
 public:
  // With a plant's return among the readings the run goes on to its end:
  // the return is read from the plant's rows afterwards.
  explicit SensorRecorder(const std::vector<Reading>& readings)
      : readings_(readings), order_(), values_(readings.size(), nan) {
    for (std::size_t k = 0; k < readings.size(); ++k)
      if (readings[k].plant_return) finish_early_ = false;
      else order_.push_back(k);
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t a, std::size_t b) { return readings[a].time < readings[b].time; });
  }

  void read_sensors(const freezing::Thermometers& thermometers, double t) override {
    for (; next_ < order_.size() && readings_[order_[next_]].time <= t * (1 + 1e-12); ++next_) {
      const Reading& r = readings_[order_[next_]];
      values_[order_[next_]] = thermometers.at(r.sensor, r.time);
    }
  }
  bool finished() const override { return finish_early_ && !order_.empty() && next_ == order_.size(); }

  const std::vector<double>& values() const { return values_; }

 private:
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Reading>& readings_;
  std::vector<std::size_t> order_;  // the thermometers' readings by time
  std::size_t next_ = 0;
  bool finish_early_ = true;
  std::vector<double> values_;
};

// A section with its plant: the circuit marched with the section at
// mid-pipe (freezing/plant_run.hpp), the thermometers read as any run's.
ForwardResult run_plant_forward(const project::Project& p, const std::vector<Reading>& readings) {
  SensorRecorder recorder(readings);
  const auto run = freezing::run_brine_circuit({freezing::mid_pipe_section(p, "", &recorder)},
                                               freezing::circuit_settings(p), project::RunOptions{});
  // The return over each exchange at the exchange's end, linear between.
  project::TemperatureSchedule returned;
  for (const auto& row : run.series) returned.points.push_back({row.time, row.return_temperature});
  ForwardResult result;
  result.summary = run.sections.front();
  result.temperatures = recorder.values();
  for (std::size_t k = 0; k < readings.size(); ++k)
    if (readings[k].plant_return) result.temperatures[k] = returned.at(readings[k].time);
  return result;
}

}  // namespace

ForwardResult run_forward(project::Project p, const std::vector<Reading>& readings, const fs::path& scratch,
                          const freezing::Model* cloud) {
  p.output.directory = scratch.string();
  p.output.vtk = false;
  p.output.report = false;
  p.numerics.error_estimate = false;
  if (p.plant) {
    auto result = run_plant_forward(p, readings);
    fs::remove_all(scratch);
    return result;
  }
  freezing::Model built = cloud ? freezing::build_model(p, freezing::copy_cloud(*cloud, p)) : freezing::build_model(p);
  SensorRecorder recorder(readings);
  ForwardResult result;
  result.summary = freezing::run_heat(p, built, {}, &recorder);
  result.temperatures = recorder.values();
  fs::remove_all(scratch);
  return result;
}

std::vector<ForwardResult> side_by_side(const std::vector<std::function<ForwardResult()>>& tasks, int jobs,
                                        int threads) {
  std::vector<ForwardResult> results(tasks.size());
  particles::side_by_side(tasks.size(), jobs, threads, [&](std::size_t i) { results[i] = tasks[i](); });
  return results;
}

}  // namespace frostwall::calibrate
