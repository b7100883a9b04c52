// Adaptive dynamic relaxation (Kilic & Madenci, Theor. Appl. Fract. Mech.
// 53, 2010): the static equilibrium F(u) = 0 of the PD solid as the steady
// state of a damped fictitious motion with unit steps,
//     v(n+1/2) = ((2 - c) v(n-1/2) + 2 F(n) / lambda) / (2 + c)
//     u(n+1)   = u(n) + v(n+1/2),
// lambda_i >= 1/4 sum_j |K_ij| (Gershgorin: here the sum of c G V_j / |xi|
// over i's bonds, doubled for the neighbours' share, with a margin of 2)
// so the unit step is stable, and one global damping c = 2 sqrt(u.K u / u.u)
// from the local diagonal stiffness K_ii = -(F_i(n)/lambda_i - F_i(n-1)/lambda_i) / v_i(n-1/2)
// (physics.md: per-thread dampings made results depend on the thread
// count), clamped to [0, 2). It stops when the RMS of a step's
// displacement increment is below tolerance x the RMS displacement (or when
// the force vanishes), starting from the u it is given (warm start).
#pragma once

#include <functional>
#include <vector>

#include "pd/solid.hpp"

namespace frostwall::pd {

struct RelaxationResult {
  int iterations = 0;
  bool converged = false;
  double increment = 0.0;  // the last step's RMS increment / RMS displacement
};

RelaxationResult relax(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT, double tolerance,
                       int max_iterations);

// The same with the solid changing on the way: bonds that break (Kilic &
// Madenci check every step; here every `check_every` iterations and
// whenever it would stop) and held particles that follow the rest (pores
// riding on their ring). adjust() makes those changes at u and returns
// true when it changed anything; the relaxation stops only at an
// equilibrium where it changes nothing.
RelaxationResult relax_adjusting(const PdSolid& solid, std::vector<double>& u, const std::vector<double>& dT,
                                 double tolerance, int max_iterations, const std::function<bool()>& adjust,
                                 int check_every = 50);

}  // namespace frostwall::pd
