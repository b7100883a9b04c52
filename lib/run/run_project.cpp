#include "run/run_project.hpp"

#include <stdexcept>

#include "cfd_dem/run.hpp"
#include "freezing/heat_run.hpp"
#include "mechanics/engine.hpp"
#include "run/error_estimate.hpp"

namespace frostwall::run {

Engine engine_of(const project::Project& p) {
  if (p.cfd_dem) return Engine::cfd_dem;
  return mechanics::runs(p) ? Engine::mechanics : Engine::freezing;
}

summary::Summary run_engine(const project::Project& p, const RunOptions& options) {
  switch (engine_of(p)) {
    case Engine::cfd_dem: return cfd_dem::run_cfd_dem(p, options);
    case Engine::mechanics: return mechanics::run(p, options);
    case Engine::freezing: return freezing::run(p, options);
  }
  throw std::logic_error("run_engine: an engine without a run");
}

summary::Summary run_project(const project::Project& p, const RunOptions& options) {
  if (!p.layers.empty())  // study::run_layers runs them, one project per layer
    throw project::ProjectError({"layers: a layered project runs with `frostwall run`, one cross-section per layer"});
  summary::Summary s = run_engine(p, options);
  // Another packing is not a coarser grid: CFD-DEM runs have no estimate.
  if (p.numerics.error_estimate && engine_of(p) != Engine::cfd_dem) add_error_estimate(p, options, run_engine, s);
  return s;
}

}  // namespace frostwall::run
