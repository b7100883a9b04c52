// Values of a field given on a set of points (a solid's free particles),
// read at fixed places (sensors) by moving least squares, linear: exact
// for a linear field, also at a corner where the points lie on one side
// only (a Shepard mean there reads a point half a spacing inside). Used
// for the displacement and damage of PD runs, whose fields live on the
// free particles alone (the thermal layers beyond a face are not solid).
#pragma once

#include <cstdint>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::post {

class LinearProbe {
 public:
  // radius: the support (grown until at least six points are in it).
  LinearProbe(const std::vector<particles::Vec<2>>& points, const std::vector<particles::Vec<2>>& where, double radius);
  std::size_t size() const { return start_.size() - 1; }
  double at(std::size_t k, const std::vector<double>& field) const;  // field: one value per point
  // The same for a field of `stride` values per point, component c.
  double at(std::size_t k, const std::vector<double>& field, int stride, int c) const;

 private:
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> index_;
  std::vector<double> weight_;
};

}  // namespace frostwall::post
