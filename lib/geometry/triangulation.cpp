#include "geometry/triangulation.hpp"

#include <utility>

#include "geometry/delaunay.hpp"

namespace frostwall::geometry {

namespace {

IndexedDelaunay triangulate(const std::vector<particles::Vec<2>>& points) {
  std::vector<std::pair<Kernel2::Point_2, std::size_t>> input;
  input.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) input.emplace_back(Kernel2::Point_2(points[i][0], points[i][1]), i);
  return IndexedDelaunay(input.begin(), input.end());
}

std::uint32_t index(std::size_t i) { return static_cast<std::uint32_t>(i); }

}  // namespace

std::vector<std::array<std::uint32_t, 3>> delaunay_faces(const std::vector<particles::Vec<2>>& points) {
  const IndexedDelaunay dt = triangulate(points);
  std::vector<std::array<std::uint32_t, 3>> faces;
  faces.reserve(dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    faces.push_back({index(f->vertex(0)->info()), index(f->vertex(1)->info()), index(f->vertex(2)->info())});
  return faces;
}

std::vector<std::array<std::uint32_t, 2>> delaunay_edges(const std::vector<particles::Vec<2>>& points) {
  const IndexedDelaunay dt = triangulate(points);
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
    edges.push_back(
        {index(e->first->vertex(dt.cw(e->second))->info()), index(e->first->vertex(dt.ccw(e->second))->info())});
  return edges;
}

}  // namespace frostwall::geometry
