#include "freezing/excavation_face.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace frostwall::freezing {

namespace {
constexpr const char* face_name = "face";
}

void add_face_node(geometry::ShaftScene& scene, const project::Project& p) {
  const auto& e = *p.excavation;
  geometry::FixedTemperatureBoundary face;
  face.name = face_name;
  face.temperature = project::TemperatureSchedule::fixed(p.domain.initial_temperature);
  geometry::FilmWall film;
  film.heat_transfer_coefficient = e.heat_transfer;
  film.perimeter = {0.0};  // set when the face forms
  auto& P = scene.particles;
  const int id = static_cast<int>(scene.boundaries.size());
  scene.boundaries.push_back(std::move(face));
  P.add({0.0, 0.0}, P.spacing * P.spacing, id);
  if (P.graded()) P.local_spacing.push_back(P.spacing);
  film.group.assign(P.size() - P.n_free, -1);
  film.group.back() = 0;
  scene.boundaries.back().film = std::move(film);
}

int face_boundary(const geometry::Scene& scene) {
  for (std::size_t b = 0; b < scene.boundaries.size(); ++b)
    if (scene.boundaries[b].name == face_name) return static_cast<int>(b);
  return -1;
}

std::uint32_t face_particle(const geometry::Scene& scene) {
  const int b = face_boundary(scene);
  const auto& P = scene.particles;
  for (std::size_t i = P.n_free; i < P.size(); ++i)
    if (P.boundary[i] == b) return static_cast<std::uint32_t>(i);
  throw std::logic_error("face_particle: the scene has no face");
}

void add_face_pairs(particles::PairWeights& pairs, const particles::ParticleSet<2>& P, std::uint32_t node,
                    double r_inner, double r_outer) {
  const int D = pairs.dim;
  const bool directions = !pairs.direction2.empty(), vectors = !pairs.vector.empty();
  particles::PairWeights out = pairs;
  out.column.clear(), out.weight.clear(), out.direction2.clear(), out.vector.clear();
  out.row_start.assign(1, 0);
  for (std::size_t i = 0; i < pairs.n_free; ++i) {
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      if (pairs.column[e] == node) continue;
      out.column.push_back(pairs.column[e]);
      out.weight.push_back(pairs.weight[e]);
      for (int d = 0; d < D && directions; ++d) out.direction2.push_back(pairs.direction2[e * D + d]);
      for (int d = 0; d < D && vectors; ++d) out.vector.push_back(pairs.vector[e * D + d]);
    }
    const double r = P.position[i].norm();
    if (r >= r_inner && r < r_outer) {
      out.column.push_back(node);
      out.weight.push_back(0.0);
      // The pair runs along the radius, inward.
      for (int d = 0; d < D && directions; ++d) out.direction2.push_back(std::pow(P.position[i][d] / r, 2));
      for (int d = 0; d < D && vectors; ++d) out.vector.push_back(-P.position[i][d]);
    }
    out.row_start.push_back(out.column.size());
  }
  pairs = std::move(out);
}

std::vector<FaceWeight> face_weights(const particles::PairWeights& pairs, const particles::ParticleSet<2>& P,
                                     std::uint32_t node, double a, double share, const std::vector<char>& side,
                                     double reach) {
  std::vector<FaceWeight> weights;
  double drawn = 0.0;  // sum_i V_i w_i L_i
  for (std::size_t i = 0; i < pairs.n_free; ++i) {
    if (!side[i]) continue;
    const double r = P.position[i].norm(), s = P.spacing_of(i);
    if (r < a || r >= a + reach * s) continue;
    std::size_t to_node = pairs.column.size();
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e)
      if (pairs.column[e] == node) to_node = e;
    if (to_node == pairs.column.size()) throw std::logic_error("face_weights: a face particle without its face pair");
    // A particle nearly on the face would pin it alone: its logarithm is
    // taken no smaller than a quarter spacing out.
    const double L = std::log(std::max(r, a + 0.25 * s) / a);
    double row = 0.0;
    for (std::size_t e = pairs.row_start[i]; e < pairs.row_start[i + 1]; ++e) {
      const std::uint32_t j = pairs.column[e];
      if (j == node || pairs.weight[e] == 0.0) continue;
      row += pairs.weight[e] * (std::log(P.position[j].norm() / a) - std::log(r / a));
    }
    const double w = std::max(0.0, row / L);
    if (w <= 0.0) continue;
    weights.push_back({static_cast<std::uint32_t>(i), to_node, w});
    drawn += P.volume[i] * w * std::log(r / a);
  }
  if (!(drawn > 0.0))
    throw std::runtime_error("the excavation's face found no particle to join: is the cloud too coarse there?");
  const double scale = std::numbers::pi * share / drawn;
  for (auto& w : weights) w.weight *= scale;
  return weights;
}

}  // namespace frostwall::freezing
