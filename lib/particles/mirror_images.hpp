// Mirror images: the points that make symmetry planes adiabatic (SPH) or
// traction-free by symmetry (PD), and the images round a wedge's apex.
// Shared by every engine and by the geometry that places and measures
// particles.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "particles/particle_set.hpp"

namespace frostwall::particles {

// Mirror images of real particles within reach (2h) of a free particle,
// through every composition of the mirror planes that still reaches the
// domain (corners, wedge apex). source[k] is the real particle imaged.
template <int Dim>
struct MirrorImages {
  std::vector<Vec<Dim>> position;
  std::vector<std::uint32_t> source;
  // The linear part A of the isometry that made each image (y = A x + b):
  // vectors and tensors at the source map to the image through it.
  std::vector<Eigen::Matrix<double, Dim, Dim>> linear;
};
// own_reach (optional, one per particle): an image of particle j further
// than own_reach[j] beyond a plane is not wanted either (a graded cloud's
// fine particles need images only a few of their own spacings out).
template <int Dim>
MirrorImages<Dim> mirror_images(const ParticleSet<Dim>& particles, double reach,
                                const std::vector<double>& own_reach = {});

}  // namespace frostwall::particles
