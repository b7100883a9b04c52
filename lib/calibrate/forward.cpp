#include "calibrate/forward.hpp"

#include <algorithm>
#include <numeric>

#include "freezing/heat_run.hpp"
#include "particles/side_by_side.hpp"
#include "freezing/sensor_points.hpp"
#include "post/field_sampler.hpp"

namespace frostwall::calibrate {

namespace fs = std::filesystem;
using project::Reading;

namespace {

// Reads the sensors at the readings' times during a heat run: the probe's
// values after each step, interpolated linearly in time from the step
// before (the run starts from the initial field).
class SensorRecorder : public freezing::RunExtension {
 public:
  SensorRecorder(const project::Project& p, const freezing::Model& m, const std::vector<Reading>& readings)
      : probe_(post::FieldSampler(m.particles(), *m.kernel, m.smoothing), freezing::sensor_points(p, m)),
        readings_(readings),
        order_(readings.size()),
        values_(readings.size(), std::numeric_limits<double>::quiet_NaN()) {
    std::iota(order_.begin(), order_.end(), std::size_t{0});
    std::stable_sort(order_.begin(), order_.end(),
                     [&](std::size_t a, std::size_t b) { return readings[a].time < readings[b].time; });
    before_ = probe_(m.model->temperature());
  }

  void after_step(const thermal::ThermalModel& m, double t) override {
    if (next_ == order_.size()) return;
    const auto now = probe_(m.temperature());
    for (; next_ < order_.size() && readings_[order_[next_]].time <= t * (1 + 1e-12); ++next_) {
      const Reading& r = readings_[order_[next_]];
      const double w = t > t_before_ ? std::clamp((r.time - t_before_) / (t - t_before_), 0.0, 1.0) : 1.0;
      values_[order_[next_]] = before_[r.sensor] + w * (now[r.sensor] - before_[r.sensor]);
    }
    before_ = now;
    t_before_ = t;
  }

  const std::vector<double>& values() const { return values_; }

 private:
  post::PointProbe probe_;
  const std::vector<Reading>& readings_;
  std::vector<std::size_t> order_;  // readings by time
  std::size_t next_ = 0;
  std::vector<double> values_, before_;
  double t_before_ = 0.0;
};

}  // namespace

ForwardResult run_forward(project::Project p, const std::vector<Reading>& readings, double end, const fs::path& scratch,
                          const freezing::Model* cloud) {
  p.time.end = end;
  std::erase_if(p.time.snapshots, [&](double s) { return s > end * (1 + 1e-12); });
  if (p.time.snapshots.empty() || p.time.snapshots.back() < end * (1 - 1e-12)) p.time.snapshots.push_back(end);
  p.output.directory = scratch.string();
  p.output.vtk = false;
  p.output.report = false;
  p.numerics.error_estimate = false;
  freezing::Model built = cloud ? freezing::build_model(p, freezing::copy_cloud(*cloud, p)) : freezing::build_model(p);
  SensorRecorder recorder(p, built, readings);
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
