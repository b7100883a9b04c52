// Points and vectors of the particle cloud. Dim is 2 today; the engine is
// written against Vec<Dim> so a 3-D model is a template argument, not a rewrite.
#pragma once

#include <Eigen/Core>

namespace frostwall::particles {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

}  // namespace frostwall::particles
