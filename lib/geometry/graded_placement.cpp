#include "geometry/graded_placement.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "particles/mirror_images.hpp"
#include "geometry/delaunay.hpp"
#include "particles/parallel.hpp"

namespace frostwall::geometry {

namespace {

// Lloyd stops once no particle moves more than this many of its spacings.
constexpr double settled_move = 0.05;

using K = Kernel2;
using MeshVertex = CGAL::Delaunay_mesh_vertex_base_2<K>;
using MeshFace = CGAL::Delaunay_mesh_face_base_2<K>;
using MeshCDT =
    CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<MeshVertex, MeshFace>>;

// CGAL's size criterion with the size field in place of one global bound:
// a triangle is too big when its longest edge exceeds factor * s(centroid).
// The angle criterion (smallest angle above ~20.7 deg) is CGAL's.
class SizeFieldCriteria : public CGAL::Delaunay_mesh_size_criteria_2<MeshCDT> {
  using Base = CGAL::Delaunay_mesh_size_criteria_2<MeshCDT>;

 public:
  using Quality = Base::Quality;
  SizeFieldCriteria(const SizeField& size, double factor) : Base(0.125, 0.0), size_(&size), factor_(factor) {}

  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(const SizeField* size, double factor, double aspect, const K& traits)
        : Base::Is_bad(aspect, 0.0, traits), size_(size), factor_(factor) {}
    using Base::Is_bad::operator();
    CGAL::Mesh_2::Face_badness operator()(const MeshCDT::Face_handle& fh, Quality& q) const {
      const K::Point_2& a = fh->vertex(0)->point();
      const K::Point_2& b = fh->vertex(1)->point();
      const K::Point_2& c = fh->vertex(2)->point();
      double e[3] = {CGAL::squared_distance(b, c), CGAL::squared_distance(c, a), CGAL::squared_distance(a, b)};
      std::sort(e, e + 3);
      const Vec2 centroid((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
      const double bound = factor_ * (*size_)(centroid);
      q.second = e[2] / (bound * bound);
      if (q.size() > 1) {
        q.first = 1;
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double area = 2.0 * CGAL::area(a, b, c);
      q.first = area * area / (e[2] * e[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const SizeField* size_;
    double factor_;
  };
  Is_bad is_bad_object() const { return Is_bad(size_, factor_, this->bound(), this->traits); }

 private:
  const SizeField* size_;
  double factor_;
};

// Far enough from every boundary for a seed: Lloyd pulls it where it belongs.
bool clear_of_boundaries(const PlacementRegion& region, const SizeField& size, const Vec2& x) {
  const double s = size(x);
  if (!region.inside(x)) return false;
  for (const auto& m : region.mirrors)
    if (m.distance(x) < 0.3 * s) return false;
  for (const auto& w : region.walls)
    if (w.distance(x) < 0.3 * s) return false;
  return true;
}

// Seeds: the mesher's triangles, each standing for area / s^2 particles,
// taken in Morton order of their centroids (neighbours in space follow
// each other) with the shares added up; a seed goes to the centroid of the
// triangle where the sum passes a whole number. So every patch of a few
// triangles gets its count, also where the region is narrower than the
// spacing (a wedge's apex), where the mesher's own vertices lie on the
// sides.
std::vector<Vec2> seeds(const PlacementRegion& region, const SizeField& size) {
  MeshCDT cdt;
  for (std::size_t k = 0; k < region.outline.size(); ++k) {
    const Vec2& a = region.outline[k];
    const Vec2& b = region.outline[(k + 1) % region.outline.size()];
    cdt.insert_constraint(K::Point_2(a[0], a[1]), K::Point_2(b[0], b[1]));
  }
  CGAL::refine_Delaunay_mesh_2(cdt, SizeFieldCriteria(size, 1.0));

  struct Share {
    std::uint64_t key;
    Vec2 centroid;
    double count;
  };
  std::vector<Share> shares;
  Vec2 lo = Vec2::Constant(1e300);
  for (const auto& x : region.outline) lo = lo.cwiseMin(x);
  const double cell = 0.5 * size.finest();
  auto morton = [&](const Vec2& x) {
    const auto a = static_cast<std::uint64_t>(std::max(0.0, (x[0] - lo[0]) / cell));
    const auto b = static_cast<std::uint64_t>(std::max(0.0, (x[1] - lo[1]) / cell));
    std::uint64_t key = 0;
    for (int bit = 0; bit < 32; ++bit) key |= ((a >> bit) & 1u) << (2 * bit) | ((b >> bit) & 1u) << (2 * bit + 1);
    return key;
  };
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    const auto& a = f->vertex(0)->point();
    const auto& b = f->vertex(1)->point();
    const auto& c = f->vertex(2)->point();
    const Vec2 g((a.x() + b.x() + c.x()) / 3.0, (a.y() + b.y() + c.y()) / 3.0);
    if (!region.inside(g)) continue;  // e.g. in a pipe disc: that ground is the pipe's
    const double s = size(g);
    shares.push_back({morton(g), g, CGAL::area(a, b, c) / (s * s)});
  }
  std::sort(shares.begin(), shares.end(), [](const Share& a, const Share& b) { return a.key < b.key; });
  double sum = 0.0;
  std::vector<Vec2> points;
  for (const auto& share : shares) {
    sum += share.count;
    if (sum >= 0.5 && clear_of_boundaries(region, size, share.centroid)) {
      points.push_back(share.centroid);
      sum -= 1.0;
    }
  }
  return points;
}

}  // namespace

std::vector<Vec2> place_graded(const PlacementRegion& region, const SizeField& size, int iterations,
                               PlacementReport* report) {
  PlacementReport r;
  std::vector<Vec2> points = seeds(region, size);
  r.particles = points.size();
  const double reach = 2.5 * size.coarsest();
  for (int it = 0; it < iterations; ++it) {
    // Everything that bounds a free particle's cell: free, fixed, wall
    // reflections of free particles near a wall, and mirror images of all.
    particles::ParticleSet<2> cloud;
    cloud.spacing = size.finest();
    cloud.mirrors = region.mirrors;
    for (const auto& x : points) cloud.add(x, 0.0, -1);
    cloud.n_free = points.size();
    for (const auto& x : region.fixed) cloud.add(x, 0.0, 0);
    for (const auto& w : region.walls)
      for (const auto& x : points)
        if (w.distance(x) < 2.5 * size(x)) cloud.add(w.reflect(x), 0.0, 0);
    // A cell is bounded by neighbours a spacing or so away: images of
    // points within 2.5 of their own spacings of a mirror are enough (the
    // coarsest spacing's reach imaged most of a narrow wedge, and tripled
    // the triangulation).
    std::vector<double> own_reach(cloud.size());
    for (std::size_t i = 0; i < cloud.size(); ++i) own_reach[i] = 2.5 * size(cloud.position[i]);
    const auto images = particles::mirror_images(cloud, reach, own_reach);

    constexpr std::size_t not_free = static_cast<std::size_t>(-1);
    std::vector<std::pair<K::Point_2, std::size_t>> input;
    input.reserve(cloud.size() + images.position.size());
    for (std::size_t i = 0; i < cloud.size(); ++i)
      input.emplace_back(K::Point_2(cloud.position[i][0], cloud.position[i][1]), cloud.is_free(i) ? i : not_free);
    for (const auto& y : images.position) input.emplace_back(K::Point_2(y[0], y[1]), not_free);
    const IndexedDelaunay dt(input.begin(), input.end());

    // Each free point to the density-weighted centroid of its Voronoi cell
    // (the triangulation is only read: the points run in parallel).
    std::vector<IndexedDelaunay::Vertex_handle> vertex(points.size());
    for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
      if (v->info() != not_free) vertex[v->info()] = v;
    std::vector<Vec2> moved = points;
    const double largest = particles::max_over_particles(points.size(), [&](std::size_t i) {
      if (vertex[i] == IndexedDelaunay::Vertex_handle()) return 0.0;  // merged with a coincident point
      const Vec2 xi = points[i];
      auto f = dt.incident_faces(vertex[i]), done = f;
      std::vector<Vec2> corners;
      do {
        if (dt.is_infinite(f)) return 0.0;  // unbounded cell
        const auto c = dt.circumcenter(f);
        corners.emplace_back(c.x(), c.y());
      } while (++f != done);
      // Density-weighted centroid over the triangles (x_i, c_k, c_k+1),
      // density s^-4 at each triangle's centroid.
      Vec2 sum = Vec2::Zero();
      double mass = 0.0;
      for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec2& a = corners[k];
        const Vec2& b = corners[(k + 1) % corners.size()];
        const double area = 0.5 * ((a - xi)[0] * (b - xi)[1] - (a - xi)[1] * (b - xi)[0]);
        const Vec2 g = (xi + a + b) / 3.0;
        const double s = size(g);
        const double w = area / (s * s * s * s);
        sum += w * g;
        mass += w;
      }
      if (!(mass > 0.0)) return 0.0;
      const Vec2 target = sum / mass;
      if (!region.inside(target)) return 0.0;
      moved[i] = target;
      return (target - xi).norm() / size(xi);
    });
    points = std::move(moved);
    r.iterations = it + 1;
    r.last_move = largest;
    // Settled: on the single ring, stopping here (about 20 iterations)
    // instead of after 40 moved the closure day by 0.07 % and the wall
    // thickness by 0.2 cm, well inside the spacing's own error.
    if (largest < settled_move) break;
  }
  if (report) *report = r;
  return points;
}

double assign_free_spacing(particles::ParticleSet<2>& P, const SizeField& size) {
  double volume = 0.0, squares = 0.0;
  for (std::size_t i = 0; i < P.n_free; ++i) {
    volume += P.volume[i];
    squares += size(P.position[i]) * size(P.position[i]);
  }
  const double scale = std::sqrt(volume / squares);
  P.local_spacing.resize(P.size(), 0.0);
  for (std::size_t i = 0; i < P.n_free; ++i) P.local_spacing[i] = scale * size(P.position[i]);
  return scale;
}

}  // namespace frostwall::geometry
