// The Darcy flux at each free particle, q_i = -k_r,i grad psi_i, with the
// gradient a weighted least-squares fit of the potential over the
// particles (and mirror images) within `reach`: a plane through psi_i,
// exact for a linear potential even where the neighbours lie on one side
// only (beside a pipe, whose particles carry no potential), which a kernel
// sum is not. For the report, the VTU and the checks; the heat the water
// carries uses the solver's pair fluxes, not these.
#pragma once

#include <vector>

#include "particles/particle_set.hpp"

namespace frostwall::porous_flow {

// potential: every particle's (NaN: no flow, skipped). Returns one vector
// per free particle, m/s when psi is in m^2/s.
std::vector<particles::Vec<2>> darcy_flux_at_particles(const particles::ParticleSet<2>& cloud,
                                                        const std::vector<double>& potential,
                                                        const std::vector<double>& relative_permeability, double reach);

}  // namespace frostwall::porous_flow
