// Isolines of a field sampled at scattered points (the frozen front is the
// 0.5 liquid-fraction isoline): marching triangles on the Delaunay
// triangulation of the points, i.e. the level set of the piecewise-linear
// interpolant, so a field linear in x is reproduced exactly.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "geometry/cloud_mesh.hpp"
#include "geometry/polyline.hpp"
#include "particles/vec.hpp"

namespace frostwall::post {

using geometry::Polyline;

// Every isoline f = level of the field values[i] given at points[i].
//  - A value equal to level counts as above (values >= level are "above").
//  - Each polyline keeps the region below level on its left: a curve around
//    a region below level runs counterclockwise.
//  - Triangles whose longest edge exceeds max_edge are skipped, so the long
//    slivers that the Delaunay triangulation puts across holes (pipe discs
//    without particles) and concave parts of the hull carry no front; an
//    isoline then ends there (open). A few particle spacings is a good limit.
//  - Coincident points are triangulated once (one of their values is used).
//  - A region above level of zero area (points exactly at level surrounded
//    by values below) gives a closed polyline of at most two points, or none.
// Throws std::invalid_argument on mismatched sizes, non-finite values or
// level, or max_edge not > 0.
std::vector<Polyline> isolines(const std::vector<particles::Vec<2>>& points, const std::vector<double>& values,
                               double level, double max_edge = std::numeric_limits<double>::infinity());

// The same on a graded cloud: each point has its own limit (a few of its
// local spacings); a triangle is skipped when its longest edge exceeds the
// largest limit of its three corners.
std::vector<Polyline> isolines(const std::vector<particles::Vec<2>>& points, const std::vector<double>& values,
                               double level, const std::vector<double>& max_edge_at);

// The pieces of each polyline inside a region (inside(x) true), in order;
// a polyline kept whole keeps its closedness, pieces are open.
template <class Inside>
std::vector<Polyline> clip_polylines(const std::vector<Polyline>& lines, Inside&& inside) {
  std::vector<Polyline> kept;
  for (const auto& line : lines) {
    Polyline piece;
    auto flush = [&] {
      if (piece.points.size() > 1) kept.push_back(piece);
      piece = {};
    };
    for (const auto& x : line.points) {
      if (inside(x)) piece.points.push_back(x);
      else flush();
    }
    if (piece.points.size() == line.points.size()) piece.closed = line.closed;
    flush();
  }
  return kept;
}

// The same, with the triangulation built once for points that do not move
// (our particles): each call then costs one pass over the triangles.
class IsolineMesh {
 public:
  IsolineMesh(std::vector<particles::Vec<2>> points, double max_edge = std::numeric_limits<double>::infinity());
  IsolineMesh(std::vector<particles::Vec<2>> points, const std::vector<double>& max_edge_at);
  // Triangles given (counterclockwise, indices into points).
  IsolineMesh(std::vector<particles::Vec<2>> points, std::vector<geometry::Triangle> triangles)
      : points_(std::move(points)), triangles_(std::move(triangles)) {}
  std::vector<Polyline> isolines(const std::vector<double>& values, double level) const;
  std::size_t size() const { return points_.size(); }
  const std::vector<particles::Vec<2>>& points() const { return points_; }
  const std::vector<geometry::Triangle>& triangles() const { return triangles_; }

 private:
  std::vector<particles::Vec<2>> points_;
  std::vector<geometry::Triangle> triangles_;  // counterclockwise, longest edge <= max_edge
};

}  // namespace frostwall::post
