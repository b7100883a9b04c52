// Closure per gap between two neighbouring pipes of a ring: the day a
// fully frozen path joins the two pipe walls inside the gap's sector (the
// ground between the rays from the ring's centre through the two pipe
// centres), as the wall's closure (post/closure.hpp) is a fully frozen path
// round the shaft. The path runs along the Delaunay links of the sector's
// free particles, and the gap's measure is the bottleneck of g = H /
// H_latent along it (the smallest level at which particles with g at or
// below it join the two walls): the gap is closed when it is at or below 0,
// interpolated between observations. A gap that a mirror line cuts joins
// its pipe to the mirror line (the path's image closes the other half).
// Also kept: the day the straight bridge between the pipe centres is fully
// frozen (every free particle within 0.75 of its own spacing of the
// segment), the later, conservative day where the columns meet off the
// line (a flow bending them). Gaps outside the simulated wedge (no
// particles near them) are left out: the mirror images of those in it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/layout.hpp"
#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"
#include "post/link_graph.hpp"

namespace frostwall::post {

struct Gap {
  std::string between;         // "outer 3 - outer 4"
  particles::Vec<2> middle;    // the segment's midpoint (m)
  particles::Vec<2> from, to;  // the pipe centres
  // The part of the segment inside the simulated section, and how many
  // such parts the whole gap has (2 when a mirror line cuts it).
  particles::Vec<2> inside_from, inside_to;
  double copies = 1.0;
  std::vector<std::uint32_t> along;  // free particles on the segment
  // The sector's free particles, their Delaunay links (local indices) and
  // which wall each touches (bit 1: the first pipe's, bit 2: the second's).
  std::vector<std::uint32_t> sector;
  LinkGraph links;
  std::vector<char> touches;
  std::optional<double> closed;         // s: a fully frozen path between the walls
  std::optional<double> bridge_closed;  // s: the straight bridge fully frozen
  double worst = 1.0;                   // the path's bottleneck, last observed
  double bridge_worst = 1.0;            // the largest latent share left along the bridge
  double falling = 0.0;                 // -d worst / dt between the last two observations (1/s)
  // The water through the gap at each flow solve: (s, m^2/s per metre of
  // depth, the magnitude).
  std::vector<std::pair<double, double>> flow;
};

class GapClosure {
 public:
  // pipe_radius: a free particle within one of its spacings of a pipe's
  // wall touches it (the first ring of particles), and within 0.75 of a
  // mirror line through the gap touches the line (the row beside it).
  GapClosure(const particles::ParticleSet<2>& particles, const std::vector<geometry::Pipe2>& pipes, double pipe_radius);
  // latent_left: H / H_latent per particle, at time t (s).
  void observe(double t, const std::vector<double>& latent_left);
  // The flow through each gap from the pair fluxes Q_e (groundwater::
  // DarcyCloud): the sum over the pairs whose segment crosses the one
  // between the pipe centres, from one side to the other. The pair fluxes
  // balance at every particle and pipes carry none, so this is the water
  // passing between the two pipes. A gap that a mirror line cuts carries
  // twice what crosses its half in the section. Needs the pairs' vectors.
  void observe_flow(double t, const particles::ParticleSet<2>& particles, const particles::PairWeights& pairs,
                    const std::vector<double>& pair_flux);
  const std::vector<Gap>& gaps() const { return gaps_; }
  // The gap that closed last (or is still open, the most open first); null
  // without gaps.
  const Gap* last() const;
  // The time in which the fastest-closing open gap, at its present rate,
  // loses `change` of the latent share along its bridge; null while no open
  // gap is freezing. A step limit that resolves each gap's closure day.
  std::optional<double> time_to_fall(double change) const;

 private:
  // The bottleneck of g on the gap's sector links between its two walls.
  double bottleneck(const Gap& gap, const std::vector<double>& g);
  std::vector<Gap> gaps_;
  double last_t_ = 0.0;
  std::vector<std::uint32_t> order_;  // bottleneck scratch
  ComponentJoin join_;
};

}  // namespace frostwall::post
