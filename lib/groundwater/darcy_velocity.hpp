// The Darcy flux at each free particle, q_i = -k_r,i grad psi_i, the
// gradient from the particle's pairs (particles/pair_gradient.hpp: exact
// for a linear potential even beside a pipe, whose particles carry no
// potential and are skipped). For the checks and the outputs; the heat the
// water carries uses the solver's pair fluxes, not these.
#pragma once

#include <vector>

#include "particles/pair_weights.hpp"
#include "particles/vec.hpp"

namespace frostwall::groundwater {

// potential: every particle's (NaN: no flow). The pairs must carry their
// vectors. Returns one vector per free particle, m/s when psi is in m^2/s.
std::vector<particles::Vec<2>> darcy_flux_at_particles(const particles::PairWeights& pairs,
                                                       const std::vector<double>& potential,
                                                       const std::vector<double>& relative_permeability);

}  // namespace frostwall::groundwater
