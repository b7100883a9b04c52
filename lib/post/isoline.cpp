#include "post/isoline.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>

#include "geometry/cloud_mesh.hpp"

namespace frostwall::post {

namespace {
constexpr std::size_t none = static_cast<std::size_t>(-1);

// A crossing of the isoline with one Delaunay edge: the node of the
// segment graph. Every edge lies in at most two triangles, and the
// orientation rule makes it the end of one segment and the start of the
// other, so each node has at most one successor and one predecessor.
struct Crossing {
  particles::Vec<2> point;
  std::size_t next = none;
  bool has_prev = false;
  bool visited = false;
};

// Appends x unless it repeats the last point exactly: a vertex exactly at
// level is the crossing of all its edges towards values below, which
// yields zero-length segments there.
void append(std::vector<particles::Vec<2>>& out, const particles::Vec<2>& x) {
  if (out.empty() || out.back() != x) out.push_back(x);
}
}  // namespace

std::vector<Polyline> isolines(const std::vector<particles::Vec<2>>& points, const std::vector<double>& values,
                               double level, double max_edge) {
  if (values.size() != points.size()) throw std::invalid_argument("isolines: values and points differ in size");
  return IsolineMesh(points, max_edge).isolines(values, level);
}

std::vector<Polyline> isolines(const std::vector<particles::Vec<2>>& points, const std::vector<double>& values,
                               double level, const std::vector<double>& max_edge_at) {
  if (values.size() != points.size()) throw std::invalid_argument("isolines: values and points differ in size");
  return IsolineMesh(points, max_edge_at).isolines(values, level);
}

IsolineMesh::IsolineMesh(std::vector<particles::Vec<2>> points, double max_edge)
    : IsolineMesh(std::move(points), std::vector<double>{max_edge}) {}

IsolineMesh::IsolineMesh(std::vector<particles::Vec<2>> points, const std::vector<double>& max_edge_at)
    : points_(std::move(points)) {
  // cloud_triangles checks the points and limits (std::invalid_argument).
  triangles_ = geometry::cloud_triangles(points_, max_edge_at);
}

std::vector<Polyline> IsolineMesh::isolines(const std::vector<double>& values, double level) const {
  const auto& points = points_;
  if (values.size() != points.size()) throw std::invalid_argument("isolines: values and points differ in size");
  if (!std::isfinite(level)) throw std::invalid_argument("isolines: level is not finite");
  for (double v : values)
    if (!std::isfinite(v)) throw std::invalid_argument("isolines: non-finite point or value");

  // Keyed by the Delaunay edge (sorted vertex indices), so both triangles
  // of an edge meet at the same node without any floating tolerance.
  std::vector<Crossing> nodes;
  std::unordered_map<std::uint64_t, std::size_t> node_of_edge;
  auto node = [&](std::size_t i, std::size_t j) {
    if (i > j) std::swap(i, j);
    const std::uint64_t key = (static_cast<std::uint64_t>(i) << 32) | j;
    auto [it, inserted] = node_of_edge.try_emplace(key, nodes.size());
    if (inserted) {
      // One side is >= level, the other < level, so the values differ and
      // t lies in [0, 1); computed from the sorted pair, hence one value.
      const double t = (level - values[i]) / (values[j] - values[i]);
      nodes.push_back({points[i] + t * (points[j] - points[i])});
    }
    return it->second;
  };

  for (const auto& v : triangles_) {
    bool above[3];
    int n_above = 0;
    for (int k = 0; k < 3; ++k) {
      above[k] = values[v[k]] >= level;
      n_above += above[k];
    }
    if (n_above == 0 || n_above == 3) continue;
    // The vertex on its own side; the front crosses the two edges at it.
    int k = 0;
    while (above[k] != (n_above == 1)) ++k;
    const std::size_t after = node(v[k], v[(k + 1) % 3]);   // edge k -> k+1
    const std::size_t before = node(v[(k + 2) % 3], v[k]);  // edge k-1 -> k
    // Faces are counterclockwise: going from the edge after the corner to
    // the edge before it keeps the corner on the left.
    const bool corner_below = !above[k];
    const std::size_t from = corner_below ? after : before;
    const std::size_t to = corner_below ? before : after;
    if (nodes[from].next != none || nodes[to].has_prev)
      throw std::logic_error("isolines: inconsistent segment orientation");
    nodes[from].next = to;
    nodes[to].has_prev = true;
  }

  std::vector<Polyline> lines;
  auto trace = [&](std::size_t start, bool closed) {
    Polyline line;
    line.closed = closed;
    for (std::size_t n = start; n != none && !nodes[n].visited; n = nodes[n].next) {
      nodes[n].visited = true;
      append(line.points, nodes[n].point);
    }
    if (closed && line.points.size() > 1 && line.points.back() == line.points.front()) line.points.pop_back();
    if (line.points.size() >= 2) lines.push_back(std::move(line));
  };
  // Open lines start where no segment leads in (hull, skipped triangle);
  // whatever is left after them consists of cycles.
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (!nodes[n].has_prev && !nodes[n].visited) trace(n, false);
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (!nodes[n].visited) trace(n, true);
  return lines;
}

}  // namespace frostwall::post
