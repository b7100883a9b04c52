// Closure per gap: the day the straight bridge between two
// neighbouring pipes of a ring is fully frozen, i.e. the latent heat left
// (H / H_latent, as the closure detector uses) is at or below 0 at every
// free particle within 0.75 of its own spacing of the segment between the
// pipe centres. A frozen straight bridge is one frozen path through the
// gap, so the wall's closure (post/closure.hpp: any path) comes no later
// than the last gap's day; where the columns meet off the line (a flow
// bending them) the gap's day is the later, conservative one. The day is
// interpolated between observations. Gaps outside the simulated wedge
// (no particles near them) are left out: the mirror images of those in it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "geometry/layout.hpp"
#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"

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
  std::optional<double> closed;      // s
  double worst = 1.0;                // the largest latent share left along it, last observed
  double falling = 0.0;              // -d worst / dt between the last two observations (1/s)
  // The water through the gap at each flow solve: (s, m^2/s per metre of
  // depth, the magnitude).
  std::vector<std::pair<double, double>> flow;
};

class GapClosure {
 public:
  GapClosure(const particles::ParticleSet<2>& particles, const std::vector<geometry::Pipe2>& pipes);
  // latent_left: H / H_latent per particle, at time t (s).
  void observe(double t, const std::vector<double>& latent_left);
  // The flow through each gap from the pair fluxes Q_e (pore_water::
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
  std::vector<Gap> gaps_;
  double last_t_ = 0.0;
};

}  // namespace frostwall::post
