#include "thermal/thermal_model.hpp"

#include "particles/parallel.hpp"

namespace frostwall::thermal {

ThermalModel::ThermalModel(std::vector<double> volume, std::vector<int> boundary_id, particles::PairWeights pairs,
                           PhaseChangeLaw law, std::vector<FixedTemperatureBoundary> boundaries,
                           ConductionOptions options, double initial_temperature, sph::WallExtrapolation beyond_wall)
    : volume_(std::move(volume)),
      boundary_id_(std::move(boundary_id)),
      pairs_(std::move(pairs)),
      laws_{law},
      boundaries_(std::move(boundaries)),
      options_(options),
      beyond_wall_(std::move(beyond_wall)),
      anisotropic_(law.anisotropic()) {
  particles::flush_denormals_to_zero();
  const std::size_t n = volume_.size();
  H_.resize(n);
  T_.resize(n);
  f_.resize(n);
  k_.resize(2 * n);
  k_changed_.assign(n, 1);
  const double H0 = law.enthalpy(initial_temperature);
  for (std::size_t i = 0; i < n; ++i) set_state(i, H0);
  // Transpose of the pair list: where each particle appears as a neighbour.
  incoming_start_.assign(n + 1, 0);
  for (std::uint32_t j : pairs_.column) ++incoming_start_[j + 1];
  for (std::size_t p = 0; p < n; ++p) incoming_start_[p + 1] += incoming_start_[p];
  incoming_row_.resize(pairs_.pairs());
  incoming_pair_.resize(pairs_.pairs());
  std::vector<std::size_t> fill(incoming_start_.begin(), incoming_start_.end() - 1);
  for (std::size_t i = 0; i < pairs_.n_free; ++i)
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e) {
      const std::size_t slot = fill[pairs_.column[e]]++;
      incoming_row_[slot] = static_cast<std::uint32_t>(i);
      incoming_pair_[slot] = e;
    }
  for (std::size_t i = 0; i < pairs_.n_free; ++i)
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e)
      if (pairs_.column[e] >= pairs_.n_free) boundary_pairs_.emplace_back(static_cast<std::uint32_t>(i), e);
  film_wall_T_.resize(boundaries_.size());
  for (std::size_t b = 0; b < boundaries_.size(); ++b)
    if (boundaries_[b].film) film_wall_T_[b].assign(boundaries_[b].film->perimeter.size(), initial_temperature);
  apply_boundaries(0.0);
}

void ThermalModel::apply_boundaries(double t) {
  std::vector<double> T_wall(boundaries_.size());
  for (std::size_t b = 0; b < boundaries_.size(); ++b) T_wall[b] = boundaries_[b].temperature.at(t);
  const std::size_t n = pairs_.n_free;
  const bool extend = !beyond_wall_.row_start.empty();
  // The field's extension beyond the walls, E_j (on the wall: unused); a
  // film wall's temperature depends on it.
  std::vector<double> extension(size() - n, 0.0);
  if (extend)
    for (std::size_t i = n; i < size(); ++i)
      if (!beyond_wall_.on_wall(i - n)) extension[i - n] = beyond_wall_.value(i - n, T_);
  for (std::size_t b = 0; b < boundaries_.size(); ++b)
    if (boundaries_[b].film) solve_film(b, T_wall[b], extension);
  for (std::size_t i = n; i < size(); ++i) {
    const int b = boundary_id_[i];
    const auto& film = boundaries_[b].film;
    const double Tw = film ? film_wall_T_[b][film->group[i - n]] : T_wall[b];
    const double T = !extend || beyond_wall_.on_wall(i - n) ? Tw : 2.0 * Tw - extension[i - n];
    set_state(i, laws_[0].enthalpy(T));
  }
}

void ThermalModel::solve_film(std::size_t b, double T_fluid, const std::vector<double>& extension) {
  // (T_fluid: with drawn_heat, the heat drawn per metre of pipe.)
  const FilmWall& film = *boundaries_[b].film;
  const std::size_t n = pairs_.n_free;
  const bool extend = !beyond_wall_.row_start.empty();
  std::vector<double> A(film.perimeter.size(), 0.0), B(film.perimeter.size(), 0.0);
  const std::vector<double>& a = pair_coefficients();
  for (const auto& [i, e] : boundary_pairs_) {
    const std::uint32_t j = pairs_.column[e];
    if (boundary_id_[j] != int(b)) continue;
    const int g = film.group[j - n];
    const bool on_wall = !extend || beyond_wall_.on_wall(j - n);
    const double w = volume_[i] * a[e];
    A[g] += w * ((on_wall ? 0.0 : -extension[j - n]) - T_[i]);
    B[g] += w * (on_wall ? 1.0 : 2.0);
  }
  for (std::size_t g = 0; g < A.size(); ++g) {
    if (film.drawn_heat) {  // A + B T_w = -(the group's share of the heat drawn)
      const double drawn = T_fluid * film.perimeter[g] / film.full_perimeter;
      if (B[g] > 0.0) film_wall_T_[b][g] = (-drawn - A[g]) / B[g];
      continue;
    }
    const double hP = film.heat_transfer_coefficient * film.perimeter[g];
    film_wall_T_[b][g] = B[g] + hP > 0.0 ? (hP * T_fluid - A[g]) / (B[g] + hP) : T_fluid;
  }
}

void ThermalModel::set_materials(std::vector<PhaseChangeLaw> laws, std::vector<std::uint8_t> material,
                                 double initial_temperature) {
  laws_ = std::move(laws);
  material_ = std::move(material);
  material_.resize(size(), 0);
  for (const auto& law : laws_) anisotropic_ = anisotropic_ || law.anisotropic();
  for (std::size_t i = 0; i < pairs_.n_free; ++i) set_state(i, law_of(i).enthalpy(initial_temperature));
  all_changed_ = true;
}

double ThermalModel::pair_conductivity(double ki, double kj) const {
  // Both forms give 2k for equal conductivities (the Brookshaw factor).
  if (options_.mean == project::ConductivityMean::arithmetic) return ki + kj;
  return 4.0 * ki * kj / (ki + kj);
}

double ThermalModel::coefficient(std::size_t i, std::size_t j, std::size_t e) const {
  if (j >= pairs_.n_free && !one_sided_.empty() && one_sided_[boundary_id_[j]])
    return pairs_.weight[e] * 2.0 * k_[2 * i];
  return pairs_.weight[e] * (anisotropic_ ? anisotropic_factor(i, j, e) : pair_conductivity(k_[2 * i], k_[2 * j]));
}

const std::vector<double>& ThermalModel::pair_coefficients() const {
  const auto& P = pairs_;
  // The particles whose conductivity changed; many of them (a smooth
  // freezing curve changes every frozen particle's at every stage): all
  // pairs again, on every thread, rather than the changed ones one by one.
  if (!all_changed_) {
    changed_.clear();
    for (std::size_t p = 0; p < k_changed_.size(); ++p)
      if (k_changed_[p]) changed_.push_back(p);
    if (8 * changed_.size() > k_changed_.size()) all_changed_ = true;
  }
  if (all_changed_) {
    coefficient_.resize(P.pairs());
    particles::for_each_particle(P.n_free, [&](std::size_t i) {
      for (std::size_t e = P.row_start[i]; e < P.row_start[i + 1]; ++e)
        coefficient_[e] = coefficient(i, P.column[e], e);
    });
    all_changed_ = false;
    std::fill(k_changed_.begin(), k_changed_.end(), 0);
    return coefficient_;
  }
  for (const std::size_t p : changed_) {
    k_changed_[p] = 0;
    if (p < P.n_free)
      for (std::size_t e = P.row_start[p]; e < P.row_start[p + 1]; ++e)
        coefficient_[e] = coefficient(p, P.column[e], e);
    for (std::size_t s = incoming_start_[p]; s < incoming_start_[p + 1]; ++s)
      coefficient_[incoming_pair_[s]] = coefficient(incoming_row_[s], p, incoming_pair_[s]);
  }
  return coefficient_;
}

void ThermalModel::conduction_rate(std::vector<double>& rate) const {
  const std::size_t n = pairs_.n_free;
  rate.resize(n);
  const std::vector<double>& a = pair_coefficients();
  const std::size_t* start = pairs_.row_start.data();
  const std::uint32_t* column = pairs_.column.data();
  const double* T = T_.data();
  // Four partial sums: one sum would chain every pair's multiply-add on the
  // one before (the add's latency, not memory, would set the pace).
  particles::for_each_particle(n, [&](std::size_t i) {
    const double Ti = T[i];
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    std::size_t e = start[i];
    const std::size_t end = start[i + 1];
    for (; e + 4 <= end; e += 4) {
      s0 += a[e] * (T[column[e]] - Ti);
      s1 += a[e + 1] * (T[column[e + 1]] - Ti);
      s2 += a[e + 2] * (T[column[e + 2]] - Ti);
      s3 += a[e + 3] * (T[column[e + 3]] - Ti);
    }
    for (; e < end; ++e) s0 += a[e] * (T[column[e]] - Ti);
    rate[i] = (s0 + s1) + (s2 + s3);
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
  const std::vector<double>& a = pair_coefficients();
  for (const auto& [i, e] : boundary_pairs_) {
    const std::uint32_t j = P.column[e];
    heat[boundary_id_[j]] += volume_[i] * a[e] * (T_[j] - T_[i]);
  }
  return heat;
}

double ThermalModel::stored_heat() const {
  return particles::sum_over_particles(pairs_.n_free,
                                       [&](std::size_t i) { return removed(i) ? 0.0 : volume_[i] * H_[i]; });
}

void ThermalModel::remove_particles(const std::vector<std::uint32_t>& taken) {
  if (built_weight_.empty()) built_weight_ = pairs_.weight;
  removed_.resize(size(), 0);
  for (const std::uint32_t i : taken) {
    removed_[i] = 1;
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e) pairs_.weight[e] = 0.0;
    for (std::size_t s = incoming_start_[i]; s < incoming_start_[i + 1]; ++s) pairs_.weight[incoming_pair_[s]] = 0.0;
  }
  all_changed_ = true;
}

void ThermalModel::restore_particles(const std::vector<std::uint32_t>& back, std::uint8_t m, double temperature) {
  if (material_.empty()) material_.assign(size(), 0);
  for (const std::uint32_t i : back) removed_[i] = 0, material_[i] = m;
  for (const std::uint32_t i : back) {
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e)
      if (const std::uint32_t j = pairs_.column[e]; j < pairs_.n_free && !removed_[j])
        pairs_.weight[e] = built_weight_[e];
    for (std::size_t s = incoming_start_[i]; s < incoming_start_[i + 1]; ++s)
      if (!removed_[incoming_row_[s]]) pairs_.weight[incoming_pair_[s]] = built_weight_[incoming_pair_[s]];
    set_state(i, laws_[m].enthalpy(temperature));
  }
  all_changed_ = true;
}

std::uint8_t ThermalModel::add_material(const PhaseChangeLaw& law) {
  if (material_.empty()) material_.assign(size(), 0);
  if (!shared_scale_laws_) shared_scale_laws_ = laws_.size();
  laws_.push_back(law);
  anisotropic_ = anisotropic_ || law.anisotropic();
  return static_cast<std::uint8_t>(laws_.size() - 1);
}

std::size_t ThermalModel::cut_pairs(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& ends) {
  std::size_t cut = 0;
  auto cut_row = [&](std::uint32_t i, std::uint32_t j) {
    if (i >= pairs_.n_free) return;
    for (std::size_t e = pairs_.row_start[i]; e < pairs_.row_start[i + 1]; ++e)
      if (pairs_.column[e] == j && pairs_.weight[e] != 0.0) {
        pairs_.weight[e] = 0.0;
        ++cut;
      }
  };
  for (const auto& [i, j] : ends) {
    cut_row(i, j);
    cut_row(j, i);
  }
  if (cut > 0) all_changed_ = true;  // the cached coefficients are rebuilt
  return cut;
}

}  // namespace frostwall::thermal
