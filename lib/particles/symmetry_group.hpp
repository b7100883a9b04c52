// Compositions of mirror reflections: the images that make symmetry planes
// adiabatic, and the copies that rebuild a whole ring from its wedge.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "particles/particle_set.hpp"

namespace frostwall::particles {

// x -> A x + b.
template <int Dim>
struct Isometry {
  Eigen::Matrix<double, Dim, Dim> A = Eigen::Matrix<double, Dim, Dim>::Identity();
  Vec<Dim> b = Vec<Dim>::Zero();
  Vec<Dim> operator()(const Vec<Dim>& x) const { return A * x + b; }
  bool same_as(const Isometry& o, double length_scale) const {
    return (A - o.A).norm() < 1e-9 && (b - o.b).norm() < 1e-9 * length_scale;
  }
  static Isometry reflection(const MirrorPlane<Dim>& p) {
    Isometry m;
    m.A -= 2.0 * p.normal * p.normal.transpose();
    m.b = 2.0 * p.point.dot(p.normal) * p.normal;
    return m;
  }
  Isometry after(const Isometry& g) const { return {A * g.A, A * g.b + b}; }  // this o g
};

// Every element of the (finite) group the planes generate, identity first.
// Throws if the group is infinite (parallel planes) or too large.
template <int Dim>
std::vector<Isometry<Dim>> symmetry_group(const std::vector<MirrorPlane<Dim>>& planes, double length_scale);

}  // namespace frostwall::particles
