// Heat conduction with phase change on a fixed particle cloud: the state
// (enthalpy, temperature, liquid fraction, conductivity per particle) and
// the conduction operator dH_i/dt = sum_j G_ij k_ij (T_j - T_i) over the
// stored pairs. Integrators (explicit, later implicit) drive it in time.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "project/project.hpp"
#include "particles/pair_weights.hpp"
#include "particles/parallel.hpp"
#include "sph/wall_extrapolation.hpp"
#include "geometry/boundary.hpp"
#include "thermal/phase_change.hpp"

namespace frostwall::thermal {

// The fixed-temperature and film walls are laid by geometry with the scene.
using geometry::FilmWall;
using geometry::FixedTemperatureBoundary;

struct ConductionOptions {
  project::ConductivityMean mean = project::ConductivityMean::harmonic;
  // Anisotropic soils: renormalised uses the consistent pair factor
  // sum_d k_d ((Dim+2) e_d^2 - 1); plain uses the SPH paper's x/y split
  // sum_d k_d e_d^2, which mixes kx and ky (kept to reproduce the paper).
  project::LaplacianForm form = project::LaplacianForm::renormalised;
};

// The fields of particle i from its enthalpy H, through raw pointers so a
// loop over particles keeps them (and the law, passed by value) in registers.
struct StateView {
  double *H, *T, *f, *k;
  int* k_changed;
  void set(const PhaseChangeLaw& law, std::size_t i, double enthalpy) const {
    const double fi = law.liquid_fraction(enthalpy);
    const double kx = law.conductivity(fi, 0), ky = law.conductivity(fi, 1);
    H[i] = enthalpy;
    T[i] = law.temperature(enthalpy);
    f[i] = fi;
    if (kx != k[2 * i] || ky != k[2 * i + 1]) k_changed[i] = 1;
    k[2 * i] = kx;
    k[2 * i + 1] = ky;
  }
};

class ThermalModel {
 public:
  // volume and boundary_id cover all particles (free first, then fixed);
  // boundary_id[i] indexes `boundaries` for fixed particles.
  // `beyond_wall` gives the fixed particles' antisymmetric extension; when
  // empty every fixed particle holds its wall's temperature.
  ThermalModel(std::vector<double> volume, std::vector<int> boundary_id, particles::PairWeights pairs,
               PhaseChangeLaw law, std::vector<FixedTemperatureBoundary> boundaries, ConductionOptions options,
               double initial_temperature, sph::WallExtrapolation beyond_wall = {});

  std::size_t size() const { return volume_.size(); }
  std::size_t free_count() const { return pairs_.n_free; }
  // The first material's law (the soil, or a porous plate's matrix).
  const PhaseChangeLaw& law() const { return laws_[0]; }
  // Several materials (a plate and the water in its pores): laws[m] for
  // the particles of material m (fixed particles keep material 0); every
  // free particle restarts at initial_temperature.
  void set_materials(std::vector<PhaseChangeLaw> laws, std::vector<std::uint8_t> material, double initial_temperature);
  const std::vector<PhaseChangeLaw>& laws() const { return laws_; }
  double max_diffusivity() const {
    double a = 0.0;
    for (const auto& law : laws_) a = std::max(a, law.max_diffusivity());
    return a;
  }
  std::uint8_t material(std::size_t i) const { return material_.empty() ? 0 : material_[i]; }
  const PhaseChangeLaw& law_of(std::size_t i) const { return laws_[material(i)]; }
  const particles::PairWeights& pairs() const { return pairs_; }
  const std::vector<FixedTemperatureBoundary>& boundaries() const { return boundaries_; }
  // A boundary's schedule replaced during a run (the brine a coupled
  // circuit delivers); applied from the next apply_boundaries().
  void set_boundary_temperature(std::size_t b, project::TemperatureSchedule schedule) {
    boundaries_[b].temperature = std::move(schedule);
  }
  // A film wall's coefficient h replaced (the brine's film as its
  // properties change with its temperature); from the next apply_boundaries().
  void set_film_coefficient(std::size_t b, double h) { boundaries_[b].film->heat_transfer_coefficient = h; }

  // Fixed particles take their boundary's temperature at time t (on the
  // wall), or its antisymmetric extension of the current field (beyond).
  // A wall behind a film first finds its temperature from the heat balance
  // with the current field (boundary.hpp).
  void apply_boundaries(double t);
  // A film wall's temperature per group as last applied (empty: not a film wall).
  const std::vector<double>& wall_temperatures(std::size_t boundary) const { return film_wall_T_[boundary]; }
  // rate[i] = dH_i/dt for free particles (rate is resized to free_count()).
  void conduction_rate(std::vector<double>& rate) const;
  // a[e] = G_ij k_ij for every stored pair e (i, j) at the current state,
  // so that dH_i/dt = sum_e a[e] (T_j - T_i): the coefficients an implicit
  // step linearises. Kept up to date as particles change phase.
  const std::vector<double>& pair_coefficients() const;
  // Fixed particles beyond a wall: their temperature as weights over free ones.
  const sph::WallExtrapolation& beyond_wall() const { return beyond_wall_; }
  // Heat flowing into the free particles from each boundary, W (per metre
  // of depth in 2-D), at the current state: the boundary pairs alone.
  std::vector<double> boundary_heat_rate() const;
  // A crack that stops heat: the pairs between free particles i and j (both
  // ways, so the flux stays antisymmetric and energy exact) carry nothing
  // from now on. Returns how many pair entries were cut.
  std::size_t cut_pairs(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& ends);
  // Ground taken out (an excavation): every pair with one of these free
  // particles carries nothing from now on (both halves, so energy stays
  // exact), and their heat leaves stored_heat(). Their state is kept, and
  // may be set for display; nothing reads it.
  void remove_particles(const std::vector<std::uint32_t>& taken);
  // Particles taken out come back as material m at `temperature` (a lining
  // placed where the ground was): their pairs with each other and with the
  // ground still in place carry again, as first built.
  void restore_particles(const std::vector<std::uint32_t>& back, std::uint8_t m, double temperature);
  bool removed(std::size_t i) const { return !removed_.empty() && removed_[i]; }
  // A further material; returns its index. The step control holds each
  // such material's particles to their own law's enthalpy scale.
  std::uint8_t add_material(const PhaseChangeLaw& law);
  // The materials the model was built with (the first ones): they share
  // the smallest of their enthalpy scales in the step control.
  std::size_t shared_scale_laws() const { return shared_scale_laws_ ? shared_scale_laws_ : laws_.size(); }
  // Pair e's weight G set (a face joined to its wall when it forms).
  void set_pair_weight(std::size_t e, double w) {
    pairs_.weight[e] = w;
    all_changed_ = true;
  }
  // A film wall's group perimeter, m (the face moving in as a lining is placed).
  void set_film_perimeter(std::size_t b, std::size_t g, double P) { boundaries_[b].film->perimeter[g] = P; }
  // Pairs with boundary b's particles conduct with the free particle's own
  // conductivity (2 k_i) rather than the pair mean: the wall's particle
  // stands for a wall, not for a material behind it.
  void set_one_sided(std::size_t b) {
    one_sided_.resize(boundaries_.size(), 0);
    one_sided_[b] = 1;
    all_changed_ = true;
  }
  // Sets the enthalpy of free particle i and the fields derived from it.
  void set_enthalpy(std::size_t i, double H) { set_state(i, H); }
  // Sets every free particle's enthalpy to new_enthalpy(i), in one pass
  // (the integrators' update: the law's constants stay in registers).
  template <class NewEnthalpy>
  void update_free(NewEnthalpy&& new_enthalpy);
  // Heat stored in the free particles, sum V_i H_i, J (per metre in 2-D).
  double stored_heat() const;
  // H_i / H_latent of every free particle, unclamped (PhaseChangeLaw::
  // latent_left): what closure follows through 0.
  void latent_left(std::vector<double>& out) const {
    out.resize(free_count());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = law_of(i).latent_left(H_[i]);
  }

  const std::vector<double>& enthalpy() const { return H_; }
  const std::vector<double>& temperature() const { return T_; }
  const std::vector<double>& liquid_fraction() const { return f_; }
  const std::vector<double>& volume() const { return volume_; }
  // Boundary id of each particle (-1 free).
  const std::vector<int>& boundary_ids() const { return boundary_id_; }
  // Conductivity of particle i along axis d.
  double conductivity(std::size_t i, int d) const { return k_[i * 2 + d]; }

 private:
  void set_state(std::size_t i, double H);
  // The wall temperature of each group of a film wall at fluid temperature
  // T_fluid: the heat into the free particles is affine in it (on the wall
  // T_j = T_w, beyond it 2 T_w - E_j), Q = A + B T_w, and -Q = h P (T_w - T_fluid).
  void solve_film(std::size_t boundary, double T_fluid, const std::vector<double>& extension);
  StateView state_view() { return {H_.data(), T_.data(), f_.data(), k_.data(), k_changed_.data()}; }
  // a[e] of one pair, from the conductivities now.
  double coefficient(std::size_t i, std::size_t j, std::size_t e) const;
  double pair_conductivity(double ki, double kj) const;
  // Pair factor of an anisotropic soil for pair e (i, j): the consistent
  // sum_d k_d ((Dim+2) e_d^2 - 1) / 2 or the paper's sum_d k_d e_d^2.
  double anisotropic_factor(std::size_t i, std::size_t j, std::size_t e) const;

  std::vector<double> volume_;
  std::vector<int> boundary_id_;
  particles::PairWeights pairs_;
  std::vector<PhaseChangeLaw> laws_;
  std::vector<std::uint8_t> material_;  // per particle; empty: all material 0
  std::vector<FixedTemperatureBoundary> boundaries_;
  ConductionOptions options_;
  sph::WallExtrapolation beyond_wall_;
  bool anisotropic_;
  std::vector<double> H_, T_, f_, k_;
  // The pair coefficients a[e] are cached: the rate is then a plain gather
  // over the pairs, and only pairs next to a particle whose conductivity
  // changed (a freezing particle) are recomputed. incoming_* lists, per
  // particle, the pairs (row, index) in which it is the neighbour.
  mutable std::vector<double> coefficient_;
  // (int, not char: a char store may alias anything, and the state update
  // then reloaded every pointer after each flag it set.)
  mutable std::vector<int> k_changed_;
  mutable bool all_changed_ = true;
  mutable std::vector<std::size_t> changed_;  // pair_coefficients()' list, kept to reuse its memory
  std::vector<std::size_t> incoming_start_;
  std::vector<std::uint32_t> incoming_row_;
  std::vector<std::size_t> incoming_pair_;
  // Pairs whose neighbour is a fixed particle: (row, pair index).
  std::vector<std::pair<std::uint32_t, std::size_t>> boundary_pairs_;
  std::vector<std::vector<double>> film_wall_T_;  // per boundary, per group
  std::vector<char> removed_;                     // per particle; empty: none removed
  std::vector<double> built_weight_;              // the pairs' weights before any removal
  std::vector<char> one_sided_;                   // per boundary; empty: none
  std::size_t shared_scale_laws_ = 0;             // 0: every law (none added)
};

inline void ThermalModel::set_state(std::size_t i, double H) { state_view().set(law_of(i), i, H); }

template <class NewEnthalpy>
void ThermalModel::update_free(NewEnthalpy&& new_enthalpy) {
  const StateView state = state_view();
  if (material_.empty()) {  // one material: its law stays in registers
    const PhaseChangeLaw law = laws_[0];
    particles::for_each_particle(pairs_.n_free, [&](std::size_t i) { state.set(law, i, new_enthalpy(i)); });
    return;
  }
  const PhaseChangeLaw* laws = laws_.data();
  const std::uint8_t* material = material_.data();
  particles::for_each_particle(pairs_.n_free, [&](std::size_t i) { state.set(laws[material[i]], i, new_enthalpy(i)); });
}

}  // namespace frostwall::thermal
