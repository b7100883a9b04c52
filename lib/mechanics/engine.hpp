// The mechanics engine: peridynamics on a plain geometry. The heat is
// conducted by PD thermal bonds (numerics.method "pd") or SPH pairs; the
// PD solid ("mechanics") follows the temperature and the freezing pores
// ("geometry.pores") load it. It runs the heat run of lib/freezing with
// the solid and the frost as its extension.
#pragma once

#include "project/project.hpp"
#include "project/run_options.hpp"
#include "summary/summary.hpp"

namespace frostwall::mechanics {

// Whether the project is this engine's: PD heat conduction, a solid, or pores.
bool runs(const project::Project& p);

summary::Summary run(const project::Project& p, const project::RunOptions& options);

}  // namespace frostwall::mechanics
