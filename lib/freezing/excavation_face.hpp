// The excavation's face in the particle model. The shaft's air meets the
// ground (later the lining) through a wall behind a film, like brine in a
// freeze pipe (geometry/boundary.hpp): one fixed particle on the shaft's
// axis holds the face's temperature, found at every step from the heat
// balance with the film, and the particles along the face are joined to it.
//
// Each face particle i at radius r_i outside a face of radius a is joined
// by a weight w_i such that its row of the conduction operator is exact for
// the radial steady field T = T_face + C ln(r / a):
//     sum_e G_e (L_j - L_i) + w_i (0 - L_i) = 0,   L = ln(r / a),
// the particle's own pairs G_e as they stand with the ground inside the
// face taken out (the weight stands in for the pairs cut). Weights that
// come out negative are 0, and all are scaled by one factor so that the
// heat the logarithm draws is exact over the section's arc:
//     sum_i V_i w_i (2 k) L_i = 2 pi k * share.
// The pairs to the face conduct with the particle's own conductivity
// (ThermalModel::set_one_sided).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/shaft_section.hpp"
#include "particles/pair_weights.hpp"
#include "project/project.hpp"

namespace frostwall::freezing {

// Adds the face's boundary ("face": a film of excavation.heat_transfer,
// the fluid at the ground's initial temperature until the section is dug)
// and its particle on the axis to a built scene; the particle goes last.
void add_face_node(geometry::ShaftScene& scene, const project::Project& p);
// The face's boundary id and particle in a scene that has one (-1: none).
int face_boundary(const geometry::Scene& scene);
std::uint32_t face_particle(const geometry::Scene& scene);

// Rewrites `pairs`: drops every pair to the face's particle and adds one,
// of weight 0, from each free particle within [r_inner, r_outer) of the
// axis (the particles a face may later join).
void add_face_pairs(particles::PairWeights& pairs, const particles::ParticleSet<2>& P, std::uint32_t node,
                    double r_inner, double r_outer);

// The weights w_i of the face particles (`side`: the particles on the face's
// side, within `reach` local spacings of radius a), per pair entry to the
// node: (pair index, w). `share`: the part of the circle in the section.
struct FaceWeight {
  std::uint32_t particle = 0;
  std::size_t pair = 0;
  double weight = 0.0;
};
std::vector<FaceWeight> face_weights(const particles::PairWeights& pairs, const particles::ParticleSet<2>& P,
                                     std::uint32_t node, double a, double share, const std::vector<char>& side,
                                     double reach = 1.5);

}  // namespace frostwall::freezing
