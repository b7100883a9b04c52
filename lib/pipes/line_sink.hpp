// A freeze pipe as a line sink: a pipe of any size against the spacing is
// one fixed particle at its centre (the node, holding the wall's
// temperature), joined to the particles near it through the logarithmic
// profile between its wall and each of them, as a reservoir simulator joins
// a well to its cell (Peaceman's well index).
//
// Steady radial conduction round a pipe of radius a, T = T_w + C ln(r / a),
// is harmonic, and the discrete operator is made exact for it, and for a
// uniform gradient past the pipe, (r - a^2/r)(cos, sin) (each field 0 on
// the wall). For each near particle i (within `reach` of its own spacings of
// the wall) and each field phi
//     sum_e g_e G_e (phi_j - phi_i) + w_i (0 - phi_i) = 0,
// G_e the pair weights as SPH made them, g_e >= 0 a factor on the pairs
// among near particles (the same on both halves of a pair, so the flux
// stays antisymmetric and energy exact), w_i >= 0 the particle's exchange
// weight with the node (only particles within `exchange_reach` spacings of
// the wall exchange); and the heat the logarithm draws is exact,
//     sum_i V_i w_i L_i = pi * share      (L = ln(r / a); 2 pi k with 2k pairs).
// The SPH operator alone is not exact so near a logarithm: solving each
// row for w_i alone gives some negative (an unstable operator), and the
// heat drawn a few per cent off. Of the solutions, the one nearest g = 1
// and w_i from the particle's own row (weighted least change, variables
// that come out negative held at 0 and the rest solved again) is taken.
// With the pair conductivity k_ij of the particle and of the ground at the
// wall, the heat the node draws is sum_i V_i w_i k_ij (T_i - T_w) per metre.
#pragma once

#include <cstdint>
#include <vector>

#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"

namespace frostwall::pipes {

using particles::Vec;

struct LineSinkNode {
  Vec<2> centre;
  double radius = 0.0;     // the pipe's outer radius, m
  std::uint32_t node = 0;  // the fixed particle at the centre
  double share = 1.0;      // the part of the wall inside the section (1/2 on a mirror line)
};

// How the coupling came out, per pipe: what a report and a test read.
struct LineSinkFit {
  std::size_t near = 0;         // particles in the fit
  std::size_t pairs = 0;        // pairs whose factor was free
  std::size_t exchanging = 0;   // particles with w_i > 0
  double largest_change = 0.0;  // max |g - 1| over the pairs
  double residual = 0.0;        // largest |equation| / sum_e G_e over the near particles
};

struct LineSinkOptions {
  double reach = 4.0;           // near particles: within reach x their own spacing of the wall
  double exchange_cost = 1e-2;  // a change of w_i / D_i against one of a pair's factor
  double exchange_reach = 1.5;  // exchanging particles: within this many spacings of the wall
};

// Rewrites `pairs` (which must keep each pair's vector): drops the SPH pairs
// to every node, scales the pairs among each node's near particles and adds
// a pair (i, node) of weight w_i for each exchanging particle.
std::vector<LineSinkFit> couple_line_sinks(particles::PairWeights& pairs, const particles::ParticleSet<2>& particles,
                                           const std::vector<LineSinkNode>& nodes, const LineSinkOptions& options = {});

}  // namespace frostwall::pipes
