// How a freeze pipe meets the ground: one small type per model, chosen by
// name (pipe.model). The geometry asks it where the ground begins round a
// pipe and which particles the pipe itself holds; the model asks it to join
// those particles to the ground. What the pipe holds (a temperature, brine
// behind a film, a heat drawn) is the boundary's, not the exchange's.
//  - "resolved" ("disc"): rings of fixed particles on and inside the wall;
//    the SPH pairs join them to the ground.
//  - "line": one node at the centre, the ground from the wall out; the
//    exchange weights of pipes/line_sink.hpp join it.
//  - "point": one node at the centre and the SPH pairs (the SPH paper's).
#pragma once

#include <memory>
#include <vector>

#include "particles/pair_weights.hpp"
#include "particles/particle_set.hpp"
#include "pipes/line_sink.hpp"
#include "project/project.hpp"

namespace frostwall::pipes {

class PipeExchange {
 public:
  virtual ~PipeExchange() = default;
  // The pipe holds rings of fixed particles on its wall and inside (else
  // one particle at its centre).
  virtual bool rings_on_wall() const = 0;
  // No free particle nearer the pipe's centre than this; a the pipe's
  // radius, dx the spacing there.
  virtual double keep_out(double a, double dx) const = 0;
  // The exchange needs each pair's vector x_j - x_i.
  virtual bool needs_pair_vectors() const { return false; }
  // couple() changes the pair list (the SPH pairs alone join the others).
  virtual bool couples() const { return false; }
  // Joins the pipes' particles (nodes: one per pipe at its centre) to the
  // ground in the pair list.
  virtual void couple(particles::PairWeights& /*pairs*/, const particles::ParticleSet<2>& /*particles*/,
                      const std::vector<LineSinkNode>& /*nodes*/) const {}
};

std::unique_ptr<PipeExchange> make_pipe_exchange(project::PipeModel model);

}  // namespace frostwall::pipes
