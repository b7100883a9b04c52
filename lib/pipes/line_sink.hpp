// A freeze pipe as a line sink: a pipe thinner than the cloud's spacing is
// one fixed particle at its centre (the node, holding the wall's
// temperature), joined to the particles near it through the logarithmic
// profile between its wall and each of them, as a reservoir simulator joins
// a well to its cell (Peaceman's well index).
//
// Steady radial conduction round a pipe of radius a, T = T_w + C ln(r / a),
// is harmonic, and the discrete operator should be exact for it. For each
// near particle i (within `reach` of its own spacings of the centre)
//     sum_e g_e G_e (L_j - L_i) + w_i (0 - L_i) = 0,   L = ln(r / a),
// G_e the pair weights as SPH made them, g_e >= 0 a factor on the pairs
// among near particles (the same on both halves of a pair, so the flux
// stays antisymmetric and energy exact), w_i >= 0 the particle's exchange
// weight with the node. The SPH operator alone is not exact so near a
// logarithm: solving for w_i alone gives some negative (an unstable
// operator). The factors are held as close to 1 as exactness allows (a
// bounded linear least-squares problem, Ceres). With the pair conductivity
// k_ij of the particle and of the ground at the wall, the heat the node
// draws is sum_i V_i w_i k_ij (T_i - T_w) per metre: 2 pi k (T_i - T_w) /
// ln(r / a) in all for a uniform ground.
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
};

// Rewrites `pairs` (which must keep each pair's vector): drops the SPH pairs
// to every node, scales the pairs among each node's near particles and adds
// a pair (i, node) of weight w_i for each exchanging particle.
std::vector<LineSinkFit> couple_line_sinks(particles::PairWeights& pairs, const particles::ParticleSet<2>& particles,
                                           const std::vector<LineSinkNode>& nodes, const LineSinkOptions& options = {});

}  // namespace frostwall::pipes
