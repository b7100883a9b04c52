// The particle spacing a graded cloud should have at each point: the finest
// where temperatures bend sharply (at the pipe walls), a moderate one where
// the frozen wall grows, coarse far away. Each source says "spacing s_k at
// distance 0 from me, growing by `slope` per metre away", and the field is
// the smallest of them, clamped to [finest, coarsest]:
//     s(x) = clamp(min_k (s_k + slope_k d_k(x)), finest, coarsest).
// A field growing at slope g changes by a factor (1 + g) from a particle to
// its neighbour one spacing away, so g = growth - 1 bounds the ratio of
// neighbouring spacings. The minimum of such cones keeps that bound.
#pragma once

#include <functional>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::geometry {

using Vec2 = particles::Vec<2>;

class SizeField {
 public:
  SizeField(double finest, double coarsest) : finest_(finest), coarsest_(coarsest) {}

  // d(x) >= 0: the distance from the source (0 on or inside it).
  void add(std::function<double(const Vec2&)> distance, double spacing, double slope);
  // Convenience sources.
  void near_circle(const Vec2& centre, double radius, double spacing, double slope);  // a pipe wall
  void in_annulus(double r_in, double r_out, double spacing, double slope);           // a band round the axis
  void near_line(const Vec2& point, const Vec2& normal, double width, double spacing,
                 double slope);  // a strip along a face

  double operator()(const Vec2& x) const;
  double finest() const { return finest_; }
  double coarsest() const { return coarsest_; }

 private:
  struct Source {
    std::function<double(const Vec2&)> distance;
    double spacing, slope;
  };
  double finest_, coarsest_;
  std::vector<Source> sources_;
};

}  // namespace frostwall::geometry
