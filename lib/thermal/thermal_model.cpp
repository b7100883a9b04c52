#include "thermal/thermal_model.hpp"

#include "sph/parallel.hpp"

namespace frostwall::thermal {

ThermalModel::ThermalModel(std::vector<double> volume, std::vector<int> boundary_id,
                           sph::LaplacianPairs pairs, PhaseChangeLaw law,
                           std::vector<FixedTemperatureBoundary> boundaries, ConductionOptions options,
                           double initial_temperature, sph::WallExtrapolation beyond_wall)
    : volume_(std::move(volume)),
      boundary_id_(std::move(boundary_id)),
      pairs_(std::move(pairs)),
      law_(law),
      boundaries_(std::move(boundaries)),
      options_(options),
      beyond_wall_(std::move(beyond_wall)),
      anisotropic_(law_.anisotropic()) {
  sph::flush_denormals_to_zero();
  const std::size_t n = volume_.size();
  H_.resize(n);
  T_.resize(n);
  f_.resize(n);
  k_.resize(2 * n);
  const double H0 = law_.enthalpy(initial_temperature);
  for (std::size_t i = 0; i < n; ++i) set_state(i, H0);
  for (std::size_t i = 0; i < pairs_.n_free; ++i)
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e)
      if (pairs_.column[e] >= pairs_.n_free) boundary_pairs_.emplace_back(static_cast<std::uint32_t>(i), e);
  apply_boundaries(0.0);
}

void ThermalModel::set_state(std::size_t i, double H) {
  H_[i] = H;
  T_[i] = law_.temperature(H);
  f_[i] = law_.liquid_fraction(H);
  k_[2 * i] = law_.conductivity(f_[i], 0);
  k_[2 * i + 1] = law_.conductivity(f_[i], 1);
}

void ThermalModel::set_enthalpy(std::size_t i, double H) { set_state(i, H); }

void ThermalModel::apply_boundaries(double t) {
  std::vector<double> T_wall(boundaries_.size());
  for (std::size_t b = 0; b < boundaries_.size(); ++b) T_wall[b] = boundaries_[b].temperature.at(t);
  const std::size_t n = pairs_.n_free;
  const bool extend = !beyond_wall_.row_start.empty();
  for (std::size_t i = n; i < size(); ++i) {
    const double Tw = T_wall[boundary_id_[i]];
    const double T = !extend || beyond_wall_.on_wall(i - n) ? Tw : 2.0 * Tw - beyond_wall_.value(i - n, T_);
    set_state(i, law_.enthalpy(T));
  }
}

double ThermalModel::pair_conductivity(double ki, double kj) const {
  // Both forms give 2k for equal conductivities (the Brookshaw factor).
  if (options_.mean == project::ConductivityMean::arithmetic) return ki + kj;
  return 4.0 * ki * kj / (ki + kj);
}

void ThermalModel::conduction_rate(std::vector<double>& rate) const {
  const std::size_t n = pairs_.n_free;
  rate.resize(n);
  const auto& P = pairs_;
  if (!anisotropic_) {
    sph::for_each_particle(n, [&](std::size_t i) {
      const double Ti = T_[i], ki = k_[2 * i];
      double sum = 0.0;
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e) {
        const std::uint32_t j = P.column[e];
        sum += P.weight[e] * pair_conductivity(ki, k_[2 * j]) * (T_[j] - Ti);
      }
      rate[i] = sum;
    });
    return;
  }
  sph::for_each_particle(n, [&](std::size_t i) {
    const double Ti = T_[i];
    double sum = 0.0;
    for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e)
      sum += P.weight[e] * anisotropic_factor(i, P.column[e], e) * (T_[P.column[e]] - Ti);
    rate[i] = sum;
  });
}

double ThermalModel::anisotropic_factor(std::size_t i, std::size_t j, std::size_t e) const {
  const bool consistent = options_.form == project::LaplacianForm::renormalised;
  const int D = pairs_.dim;
  double factor = 0.0;
  for (int d = 0; d < 2; ++d) {
    const double kd = pair_conductivity(k_[2 * i + d], k_[2 * j + d]);
    const double e2 = pairs_.direction2[e * D + d];
    factor += consistent ? 0.5 * kd * ((D + 2) * e2 - 1.0) : kd * e2;
  }
  return factor;
}

std::vector<double> ThermalModel::boundary_heat_rate() const {
  std::vector<double> heat(boundaries_.size(), 0.0);
  const auto& P = pairs_;
  for (const auto& [i, e] : boundary_pairs_) {
    const std::uint32_t j = P.column[e];
    const double factor = anisotropic_ ? anisotropic_factor(i, j, e) : pair_conductivity(k_[2 * i], k_[2 * j]);
    heat[boundary_id_[j]] += volume_[i] * P.weight[e] * factor * (T_[j] - T_[i]);
  }
  return heat;
}

double ThermalModel::stored_heat() const {
  return sph::sum_over_particles(pairs_.n_free, [&](std::size_t i) { return volume_[i] * H_[i]; });
}

}  // namespace frostwall::thermal
