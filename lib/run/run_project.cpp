#include "run/run_project.hpp"

#include "cfd_dem/run.hpp"
#include "freezing/heat_run.hpp"
#include "mechanics/engine.hpp"

namespace frostwall::run {

Engine engine_of(const project::Project& p) {
  if (p.cfd_dem) return Engine::cfd_dem;
  return mechanics::runs(p) ? Engine::mechanics : Engine::freezing;
}

void run_project(const project::Project& p, const RunOptions& options) {
  if (!p.layers.empty())  // study::run_layers runs them, one project per layer
    throw project::ProjectError({"layers: a layered project runs with `frostwall run`, one cross-section per layer"});
  switch (engine_of(p)) {
    case Engine::cfd_dem: return cfd_dem::run_cfd_dem(p, options);
    case Engine::mechanics: return mechanics::run(p, options);
    case Engine::freezing: return freezing::run(p, options);
  }
}

}  // namespace frostwall::run
