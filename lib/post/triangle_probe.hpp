// Values of a particle field at fixed points as ParaView shows the snapshot
// files there: linear on the triangle of the particles' Delaunay
// triangulation that contains the point,
//     v(x) = l_a v_a + l_b v_b + l_c v_c,
// l the barycentric coordinates of x in the triangle (a, b, c). Exact for
// a linear field, and local: a point reads its three nearest corners only,
// so a front that passes between two particles shows in the reading when
// it passes, not smeared over a kernel's support. The points may include
// mirror images, each carrying its source particle's value, so a point on
// a symmetry plane reads the triangle across it as the unfolded ring shows.
#pragma once

#include <cstdint>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::post {

class TriangleProbe {
 public:
  // points[k] carries field[source[k]]. A place outside every triangle (off
  // the cloud) reads its nearest point.
  TriangleProbe(const std::vector<particles::Vec<2>>& points, const std::vector<std::uint32_t>& source,
                const std::vector<particles::Vec<2>>& where);

  std::size_t size() const { return weights_.size(); }
  double at(std::size_t k, const std::vector<double>& field) const;
  std::vector<double> operator()(const std::vector<double>& field) const;
  // The corners (field indices) and weights of place k, summing to one.
  struct Corner {
    std::uint32_t index;
    double weight;
  };
  const std::vector<Corner>& corners(std::size_t k) const { return weights_[k]; }

 private:
  std::vector<std::vector<Corner>> weights_;
};

}  // namespace frostwall::post
