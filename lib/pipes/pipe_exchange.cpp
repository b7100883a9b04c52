#include "pipes/pipe_exchange.hpp"

namespace frostwall::pipes {

namespace {

class ResolvedWall : public PipeExchange {
 public:
  bool rings_on_wall() const override { return true; }
  double keep_out(double a, double dx) const override { return a + 0.5 * dx; }  // the wall's own ring stands at a
};

class LineSink : public PipeExchange {
 public:
  bool rings_on_wall() const override { return false; }
  double keep_out(double a, double dx) const override { return a + 0.25 * dx; }  // the ground begins at the wall
  bool needs_pair_vectors() const override { return true; }
  bool couples() const override { return true; }
  void couple(particles::PairWeights& pairs, const particles::ParticleSet<2>& particles,
              const std::vector<LineSinkNode>& nodes) const override {
    couple_line_sinks(pairs, particles, nodes);
  }
};

class PointParticle : public PipeExchange {
 public:
  bool rings_on_wall() const override { return false; }
  double keep_out(double, double dx) const override { return 0.5 * dx; }
};

}  // namespace

std::unique_ptr<PipeExchange> make_pipe_exchange(project::PipeModel model) {
  switch (model) {
    case project::PipeModel::line: return std::make_unique<LineSink>();
    case project::PipeModel::point: return std::make_unique<PointParticle>();
    case project::PipeModel::disc: break;
  }
  return std::make_unique<ResolvedWall>();
}

}  // namespace frostwall::pipes
