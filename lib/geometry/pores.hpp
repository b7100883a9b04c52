// The pores of a porous plate on its particle cloud: which particles hold
// pore water, and which pore each belongs to.
#pragma once

#include <vector>

#include "particles/vec.hpp"
#include "project/project.hpp"

namespace frostwall::geometry {

// For each of the first n positions: the index of the pore whose disc
// holds it, or -1 (the matrix). Pores do not overlap (the loader checks).
std::vector<int> pore_membership(const std::vector<particles::Vec<2>>& position, std::size_t n,
                                 const std::vector<project::Pore>& pores);

// Each pore's frozen fraction: the volume-weighted mean of 1 - f over its
// particles (pore_of from pore_membership; f and volume per particle).
std::vector<double> pore_frozen_fraction(const std::vector<int>& pore_of, std::size_t pores,
                                         const std::vector<double>& liquid_fraction, const std::vector<double>& volume);

// Distance from x to the nearest pore rim (negative inside a pore), and
// which pore; {inf, -1} without pores.
struct NearestRim {
  double distance;
  int pore;
};
NearestRim nearest_rim(const particles::Vec<2>& x, const std::vector<project::Pore>& pores);

}  // namespace frostwall::geometry
