// Bond-update rates of the PD engine on the paper's plate (1 cm square,
// 0.1 mm spacing: 10 000 particles, horizon 3.015 spacings): the
// mechanical force loop (linear kinematics, the one the relaxation calls)
// and the thermal-bond conduction rate, on 1 and 2 threads, in one process
// (the machine is shared and noisy). The whole 200 s run is timed by
// bench/pd_plate.py through `frostwall run`.
#include <chrono>
#include <cstdio>
#include <omp.h>
#include <vector>

#include "pd/solid.hpp"
#include "project/project.hpp"
#include "timing.hpp"
#include "freezing/model.hpp"

using namespace frostwall;
using frostwall::bench::seconds_per_call;

int main() {
  project::Project p = project::load_project(FROSTWALL_SOURCE_DIR "/projects/plate_cooling.json");
  freezing::Model m = freezing::build_model(p);
  const auto& P = m.particles();
  pd::SolidGeometry g;
  g.position.assign(P.position.begin(), P.position.begin() + P.n_free);
  g.volume.assign(P.volume.begin(), P.volume.begin() + P.n_free);
  g.spacing = P.spacing;
  g.width = g.height = 0.01;
  const pd::PdSolid solid(g, *p.mechanics, pd::make_bond_law(*p.mechanics, p.numerics.horizon * P.spacing));
  std::vector<double> u(2 * solid.size(), 1e-9), dT(solid.size(), -1.0), u_all, dT_all, thermal, force, rate;
  solid.extend(u, u_all);
  solid.extend_temperature(dT, dT_all);
  solid.thermal_force(dT_all, thermal);
  std::printf("PD plate: %zu particles, %zu mechanical bonds, %zu thermal bonds\n", solid.size(), solid.bonds(),
              m.model->pairs().pairs());
  std::printf("  threads  mechanics (linear)     mechanics (nonlinear)  heat (thermal bonds)\n");
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    const double lin = seconds_per_call([&] { solid.forces_linear(u_all, thermal, force); });
    const double nonlin = seconds_per_call([&] { solid.forces_extended(u_all, dT_all, force); });
    const double heat = seconds_per_call([&] { m.model->conduction_rate(rate); });
    std::printf("  %d        %.2e bonds/s       %.2e bonds/s       %.2e bonds/s\n", threads, solid.bonds() / lin,
                solid.bonds() / nonlin, m.model->pairs().pairs() / heat);
  }
  return 0;
}
