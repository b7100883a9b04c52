// Closure (the frozen columns of neighbouring pipes join): the unfrozen
// ground around the shaft axis is cut off from the far field by frozen
// ground. On a wedge this is a frozen path from one side to the other; on
// a full ring, a frozen wall around the shaft.
//
// The detector measures how close that is with one number, the bottleneck
// b of a per-particle field g: the largest level such that particles with
// g >= b still connect the axis to the far field (links between particles
// up to 1.5 spacings apart: the lattice's 8-neighbourhood). The run passes
// g = H / H_latent, the latent heat a particle still holds (1 at the start
// of freezing, 0 fully frozen, negative once colder: unclamped, so b keeps
// falling smoothly through 0). The columns touch when b <= 0.5 (frozen =
// liquid fraction <= 0.5); the wall is closed when b <= 0: a path of fully
// frozen ground (project-format.md section 2). Near closure the neck sits
// within hundredths of a kelvin of the freezing point for days, so the
// half-frozen path forms early and drifts with resolution; the fully
// frozen one does not. b is the value of the last particle that keeps the
// gap open, so it falls continuously while that particle freezes, and both
// times are interpolated between two steps instead of snapping to one.
// On a triangulation (below) the particle graph's bottleneck is exactly
// the saddle of the piecewise-linear interpolant of g: a sub-particle
// measure, not a count of frozen particles.
//
// A graded cloud has no lattice neighbourhood: there the links are the
// edges of the Delaunay triangulation of the free particles (no longer
// than three local spacings, so no link crosses a pipe hole; in a wedge's
// apex, narrower than a spacing, the particles sit two spacings apart). A
// triangulation is planar, so a frozen wall cuts the unfrozen ground off
// exactly when it is a chain of linked particles. On a wedge the mirror
// images of the free particles are triangulated with them (a link to an
// image is a link to its source): the wedge's own hull would run along
// each mirror line, and such an edge passes between a frozen particle and
// its image, a way round the wall that the symmetric field does not have
// (a wedge then closed a day later than its full ring).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "particles/particle_set.hpp"
#include "particles/vec.hpp"
#include "post/link_graph.hpp"

namespace frostwall::post {

// Triangulations of a graded wedge with its mirror images (the closure
// links, the front curves) use links of a few local spacings: an image of
// particle j matters only up to 4.5 of its own spacings beyond a mirror
// (three spacings, and a neighbour across may be coarser). For
// mirror_images' own_reach; empty for a lattice (one reach serves).
std::vector<double> image_reach(const particles::ParticleSet<2>& particles);

class ClosureDetector {
 public:
  ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free, double spacing,
                  double far_field_radius);
  // Graded clouds: links along Delaunay edges; far-field particles within
  // 1.5 local spacings of the far-field circle.
  // image_position / image_source: mirror images of free particles (none
  // for a full ring).
  ClosureDetector(const std::vector<particles::Vec<2>>& position, std::size_t n_free,
                  const std::vector<double>& local_spacing, double far_field_radius,
                  const std::vector<particles::Vec<2>>& image_position = {},
                  const std::vector<std::uint32_t>& image_source = {});
  // The lattice rule for a lattice, the Delaunay rule for a graded cloud.
  ClosureDetector(const particles::ParticleSet<2>& particles, double far_field_radius);
  // -infinity when nothing joins the axis to the far field at any level.
  double bottleneck(const std::vector<double>& g) const;
  std::size_t links() const { return links_.link.size(); }
  // Liquid fractions: the columns touch (some path frozen to f <= 0.5).
  bool touching(const std::vector<double>& liquid_fraction) const { return bottleneck(liquid_fraction) <= 0.5; }

 private:
  static constexpr char far_field_bit = 1, axis_bit = 2;
  // Marks the ends of the path: the far field (1 for each free particle
  // next to the far-field circle) and the free particle nearest the axis.
  void set_ends(const std::vector<particles::Vec<2>>& free, std::vector<char> far_field);

  LinkGraph links_;
  std::vector<char> ends_;  // far_field_bit, axis_bit per free particle
};

// Follows the bottleneck of g = H / H_latent in time and interpolates the
// instants it crosses 0.5 (the frozen columns touch) and 0 (closure: a
// fully frozen path).
class ClosureWatch {
 public:
  static constexpr double contact_level = 0.5, closure_level = 0.0;
  explicit ClosureWatch(const ClosureDetector& detector) : detector_(detector) {}
  // Whether observe at time t would run the detector: while the gap is
  // wide open (b >= 1, nothing in it freezing) only every `min_interval`;
  // once a particle of the gap is freezing, at every call until closure.
  bool due(double t) const { return !closure_ && (t >= next_check_ || b_prev_ < 1.0); }
  // Call after each step (from t = 0 on) with the time and g per particle.
  void observe(double t, const std::vector<double>& g, double min_interval);
  std::optional<double> contact_time() const { return contact_; }
  std::optional<double> closure_time() const { return closure_; }
  // The last time the wall was seen open (not closed) and b then.
  double last_open_time() const { return t_prev_; }
  // While the gap freezes (0 < b < 1, falling): the time b takes to fall
  // by `change` at its last rate. A run holds its steps to that, so the
  // closure is resolved by steps, not bridged by one (run_project).
  std::optional<double> time_to_fall(double change) const {
    if (closure_ || !(b_prev_ < 1.0) || !(rate_ > 0.0)) return std::nullopt;
    return change / rate_;
  }

 private:
  const ClosureDetector& detector_;
  std::optional<double> contact_, closure_;
  double t_prev_ = 0.0, b_prev_ = 1.0, next_check_ = 0.0;
  double rate_ = 0.0;  // -db/dt between the last two observations
};

}  // namespace frostwall::post
