// Where the frozen wall is along rays from the shaft axis: on each ray, the
// longest frozen stretch (liquid fraction <= 0.5) that contains a pipe ring, its
// inner and outer radius and thickness = outer - inner; the summary's
// `wall` entries (OA, OB, min_thickness, mean_temperature_OB) come from a
// fan of such rays across the wedge.
#pragma once

#include <optional>
#include <vector>

#include "post/field_sampler.hpp"

namespace frostwall::post {

// inner/outer are null (and thickness 0) when the ray is not frozen at the
// ring radius: before closure on OB, where the ring runs between two pipes.
struct FrozenStretch {
  std::optional<double> inner, outer;
  double thickness = 0.0;
  bool frozen() const { return inner.has_value(); }
};

// The frozen stretch of one ray, sampled at ascending radii r with liquid
// fraction f there. The ray is taken piecewise linear between samples, so
// the ends are where that interpolant crosses 0.5 (not the nearest sample),
// and the ring radius is frozen when the interpolant is <= 0.5 there.
// Samples with a non-finite f (inside a pipe disc, beyond the particles)
// are dropped: the interpolant bridges them, so a pipe's hole counts as
// frozen when the ground on both sides is. A stretch that runs to the end
// of the sampled ray ends at that sample's radius. Null when ring_radius is
// outside the sampled range. Throws std::invalid_argument on mismatched
// sizes or radii not ascending.
FrozenStretch frozen_stretch(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                             double ring_radius);
// The same for any field and level: the stretch at or below `level` that
// contains the ring radius (the wall on a design isotherm: temperatures
// and the isotherm). frozen_stretch is this with the liquid fraction and 0.5.
FrozenStretch stretch_at_or_below(const std::vector<double>& r, const std::vector<double>& values, double level,
                                  double ring_radius);
FrozenStretch stretch_at_or_below(const std::vector<double>& r, const std::vector<double>& values, double level,
                                  const std::vector<double>& ring_radii);
// Double rings: the longest of the stretches that contain a ring radius
// (the inner ring's alone, or both rings once their stretches merge), so a
// wall that closed on its inner ring has a thickness from that day on.
FrozenStretch frozen_stretch(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                             const std::vector<double>& ring_radii);

// Mean of T over the stretch, (1 / thickness) * integral of T dr by the
// trapezoid rule on the samples inside it, with T interpolated linearly at
// its ends (exact for T linear in r). T at the single radius for a stretch
// of zero length; null when nothing is frozen. Non-finite T samples are
// dropped, like non-finite f in frozen_stretch. The liquid fraction the
// stretch came from is only checked for size.
std::optional<double> mean_over_frozen(const std::vector<double>& r, const std::vector<double>& liquid_fraction,
                                       const std::vector<double>& temperature, const FrozenStretch& stretch);

// Rays from the shaft axis across the wedge: ray k at start_angle +
// k * angle / (rays - 1), so the first ray is OA and the last OB (a full
// circle, angle >= 2 pi, uses angle / rays so no ray repeats); each sampled
// at the same radii r_min, r_min + dr, ..., r_max.
struct RayFan {
  double start_angle = 0.0;  // rad
  double angle = 0.0;        // rad
  int rays = 2;
  double r_min = 0.0, r_max = 0.0, dr = 0.0;

  // A single ring's wall is thinnest on OB by symmetry (midway between two
  // pipes), but with two rings, or pipes at their measured (off-design)
  // positions, the thinnest section can lie anywhere in the wedge, and OA
  // and OB alone would miss it. So the fan is dense: the arc between two
  // rays at the ring radius is at most one particle spacing, finer than
  // anything the particle field resolves (use the outermost ring's radius).
  static int rays_needed(double angle, double ring_radius, double spacing);

  double ray_angle(int k) const;
  std::vector<double> radii() const;
  // Every sample point, ray after ray: ray k's sample i is at k * radii().size() + i.
  std::vector<Vec2> points() const;
  // Ray k's values out of values given at points().
  std::vector<double> on_ray(const std::vector<double>& fan_values, int k) const;
};

struct WallExtents {
  std::vector<FrozenStretch> rays;  // one per ray of the fan
  double min_thickness = 0.0;       // 0 while some ray is not frozen at the ring
  int thinnest_ray = 0;             // the first ray with min_thickness
  const FrozenStretch& OA() const { return rays.front(); }
  const FrozenStretch& OB() const { return rays.back(); }
};

// values_on_fan: the liquid fraction at fan.points(); on each ray the longest
// frozen stretch containing one of ring_radii. Any field and level give the
// stretches at or below it (temperatures and the design isotherm).
WallExtents wall_extents(const RayFan& fan, const std::vector<double>& values_on_fan,
                         const std::vector<double>& ring_radii, double level = 0.5);

// Where the wall is weakest, rad: the thinnest ray's angle once every ray
// is frozen at the ring; before that, the middle of the widest run of
// unfrozen rays (the open gap), runs wrapping round a full circle.
double weakest_angle(const RayFan& fan, const WallExtents& extents);

// One snapshot's wall entry of the summary.
struct WallReading {
  WallExtents extents;
  std::optional<double> mean_temperature_OB;
  std::optional<double> mean_temperature_thinnest;  // over the thinnest ray's stretch
  // With a design isotherm: the stretches colder than it on every ray, and
  // the mean temperature over the thinnest one (empty rays without one).
  WallExtents isotherm;
  std::optional<double> isotherm_mean_temperature;
};

// A fan whose sample weights are computed once, then read at every snapshot.
class WallGauge {
 public:
  // isotherm (degC): also measure the wall colder than it.
  WallGauge(const FieldSampler& sampler, RayFan fan, std::vector<double> ring_radii,
            std::optional<double> isotherm = std::nullopt);
  const RayFan& fan() const { return fan_; }
  // The ground begins at radius r (an excavation's face): samples nearer
  // the axis are not read, and a stretch that reaches the first sample
  // beyond r begins at r.
  void set_inner_limit(double r);
  // Fields over all particles (free then fixed).
  WallReading measure(const std::vector<double>& liquid_fraction, const std::vector<double>& temperature) const;

 private:
  RayFan fan_;
  std::vector<double> ring_radii_;
  std::vector<double> radii_;
  PointProbe fan_probe_;  // OB is its last ray
  std::optional<double> isotherm_;
  std::optional<double> inner_limit_;
  std::size_t first_ = 0;  // the first sample read on each ray
  void clip(WallExtents& w) const;
  // The field at the fan's samples each ray needs for its stretches at or
  // below `level` (NaN elsewhere); read[k]: ray k's [first, last] sample read.
  std::vector<double> read_outward(const std::vector<double>& field, double level,
                                   std::vector<std::pair<std::size_t, std::size_t>>& read) const;
};

}  // namespace frostwall::post
