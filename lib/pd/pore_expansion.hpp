// Pore water that freezes and grows by volume_change (9 %): how it loads
// the solid around it (project mechanics.freezing_expansion).
//  - rim_displacement (the PD paper's): the pore particles are a held
//    loading device; the rim moves out radially by
//    u_a = R (sqrt(1 + dV F) - 1), F the pore's frozen fraction, so the
//    pore's area grows by dV F; the particles within it carry the
//    elastic field's continuation u_a R / r (the displacement an
//    infinite plate around a pushed hole has), so the matrix's bonds into
//    the pore see what a continuum's rim would. The pore is no anchor:
//    the held field is that push plus the matrix's free thermal strain at
//    the pore's mean temperature, on top of the pore's rigid translation,
//    which the relaxation finds (the pore's particles are one rigid group).
//    Until it starts to freeze a pore is a hole (no bonds into it).
//  - ice_eigenstrain: each pore particle is ice to its frozen fraction
//    phi = 1 - f: stiffness E_ice phi (water carries no bonds) and a free
//    areal strain sqrt(1 + dV phi) - 1 (a 2-D model takes the volume
//    change as an area change: 4.40 % linear at 9 %).
// A pore holds water to its degree of saturation S (project::Pore): the
// ice fills the air first and loads the solid only with the excess, in
// both models (Fagerlund's critical saturation S_cr = 1 / (1 + dV)).
#pragma once

#include <algorithm>
#include <vector>

#include "particles/vec.hpp"
#include "pd/solid.hpp"
#include "project/project.hpp"

namespace frostwall::pd {

// The areal change a pore of saturation S imposes on the solid when its
// water is frozen to phi: what ice and water take beyond the pore,
// S dV phi - (1 - S), or 0 while the ice still fits in the air. Frozen
// through (phi = 1): max(0, (1 + dV) S - 1).
double pore_excess(double volume_change, double saturation, double phi);

class PoreExpansion {
 public:
  PoreExpansion(const project::FreezingExpansion& expansion, double matrix_modulus, std::vector<project::Pore> pores,
                std::vector<int> pore_of);

  // The linear free strain that loads the solid at frozen fraction phi in
  // a pore of saturation S: the ice and water take S (1 + dV phi) of the
  // pore, so the areal excess over the pore is S dV phi - (1 - S), none
  // until the ice has filled the air (dV phi at S = 1).
  double free_strain(double phi, double saturation = 1.0) const;
  // Each pore's frozen fraction: the volume-weighted mean of 1 - f.
  std::vector<double> frozen_fraction(const std::vector<double>& liquid_fraction,
                                      const std::vector<double>& volume) const;
  // Installs the model on the solid (rim_displacement: the pore particles
  // held, one rigid group per pore).
  void prepare(PdSolid& solid);
  // The load at the liquid fractions now: each pore's rim push (the held
  // field itself is set by shape) and which pores carry bonds, or the
  // ice's stiffness and eigenstrain.
  void apply(PdSolid& solid, const std::vector<double>& liquid_fraction, const std::vector<double>& volume);
  // rim_displacement: sets each pore's held field (the radial push and
  // the matrix's free thermal strain at the pore's mean temperature
  // change dT) on top of the translation the pore has.
  void shape(const PdSolid& solid, const std::vector<double>& dT, std::vector<double>& u);
  // The held field last set (2 per particle), to go back between loads.
  const std::vector<double>& shape_field() const { return shape_; }
  void set_shape_field(std::vector<double> field) { shape_ = std::move(field); }
  // The largest rim push u_a now, m (rim_displacement).
  double largest_push() const {
    double largest = 0.0;
    for (double ua : rim_u_) largest = std::max(largest, ua);
    return largest;
  }
  bool rim_displacement() const { return expansion_.model == project::FreezingExpansion::Model::rim_displacement; }

 private:
  project::FreezingExpansion expansion_;
  double ice_ratio_;  // E_ice / E_matrix
  std::vector<project::Pore> pores_;
  std::vector<int> pore_of_;
  std::vector<double> shape_;  // the held field last set, 2 per particle
  std::vector<double> rim_u_;  // u_a of each pore at the last apply
};

}  // namespace frostwall::pd
