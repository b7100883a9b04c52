// A line heat source in a uniform Darcy flow, without
// phase change (OpenGeoSys' "moving line source" benchmark data:
// lambda 2.5 W/(m K), rho c 2.818 MJ/(m3 K), q = 1e-7 m/s, q_L = 20 W/m,
// two years). The exact temperature rise (Diao et al. 2004):
//   dT = q_L / (4 pi lambda) exp(v x / 2a)
//        * int_0^(v^2 t / 4a) (1/psi) exp(-psi - v^2 r^2 / (16 a^2 psi)) dpsi,
// v = q rho_w c_w / (rho c), a = lambda / (rho c). The cloud is half the
// plane (the flow runs along the mirror line y = 0), the far band holds
// dT = 0 and the potential -q x; conduction and the water's heat alternate
// (Strang) as in a run. Upstream, downstream and across, within 2 %.
#include <catch2/catch.hpp>
#include <cmath>
#include <fmt/core.h>
#include <numbers>

#include "groundwater/darcy_cloud.hpp"
#include "sph/kernel.hpp"
#include "sph/laplacian.hpp"
#include "thermal/heat_advection.hpp"
#include "thermal/integrator.hpp"
#include "no_phase_change_soil.hpp"

using namespace frostwall;
using particles::Vec;

namespace {

constexpr double lambda = 2.5, rho_c = 2.818e6, rho_c_w = 4.2e6, q = 1e-7, q_L = 20.0;
constexpr double years = 2.0 * 365.25 * 86400.0;
constexpr double a = lambda / rho_c, v = q * rho_c_w / rho_c;

// The exact rise, the integral taken in u = ln psi (smooth there) by the
// trapezium rule on 4 000 intervals from psi = 1e-12.
double exact_rise(const Vec<2>& x, double t) {
  const double beta = v * v * x.squaredNorm() / (16.0 * a * a), top = std::log(v * v * t / (4.0 * a)),
               bottom = std::log(1e-12);
  const int n = 4000;
  double sum = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double u = bottom + (top - bottom) * k / n, psi = std::exp(u);
    sum += (k == 0 || k == n ? 0.5 : 1.0) * std::exp(-psi - beta / psi);
  }
  return q_L / (4.0 * std::numbers::pi * lambda) * std::exp(v * x[0] / (2.0 * a)) * sum * (top - bottom) / n;
}

// Runs the case on a lattice of spacing s (rows half a spacing off the
// axes, so two particles straddle the line); returns the relative error at
// each point and a line per point for the log.
std::vector<double> line_source_errors(double s, std::string& log) {
  const double h = 1.3 * s, band = 2.0 * h + s;
  const double x0 = -30.0, x1 = 50.0, y1 = 35.0;  // ground; beyond it the far band
  particles::ParticleSet<2> cloud;
  for (int i = int(std::floor((x0 - band) / s)); (i + 0.5) * s < x1 + band; ++i)
    for (int j = 0; (j + 0.5) * s < y1 + band; ++j) {
      const Vec<2> x((i + 0.5) * s, (j + 0.5) * s);
      cloud.add(x, s * s, (x[0] < x0 || x[0] > x1 || x[1] > y1) ? 0 : -1);
    }
  cloud.spacing = s;
  cloud.mirrors = {{Vec<2>(0.0, 0.0), Vec<2>(0.0, 1.0)}};
  cloud.order_free_first();
  const sph::WendlandC2<2> kernel;
  const auto pairs =
      sph::build_laplacian_pairs<2>(cloud, kernel, {h, project::LaplacianForm::renormalised, false, false, true});
  std::vector<double> far;
  for (std::size_t j = cloud.n_free; j < cloud.size(); ++j) far.push_back(-q * cloud.position[j][0]);
  groundwater::DarcyCloud darcy(pairs, cloud.volume, far);
  darcy.solve(std::vector<double>(cloud.size(), 1.0));
  const thermal::PhaseChangeLaw ground(test::no_phase_change_soil("OGS moving line source", lambda, rho_c));
  thermal::ThermalModel model(cloud.volume, cloud.boundary, pairs, ground,
                              {{"far_field", project::TemperatureSchedule::fixed(0.0)}}, thermal::ConductionOptions{},
                              0.0);
  thermal::HeatAdvection water(rho_c_w, darcy.pair_flux());
  thermal::ExplicitEuler conduction(0.1, h);
  // The source: the particles within a spacing of the line (this half of
  // the plane takes half its heat, q_L / 2).
  std::vector<std::size_t> source;
  for (std::size_t i = 0; i < cloud.n_free; ++i)
    if (cloud.position[i].norm() < s) source.push_back(i);
  REQUIRE(!source.empty());
  const double n_steps = std::ceil(years / conduction.preferred_step(model)), dt = years / n_steps;
  model.apply_boundaries(0.0);
  for (int k = 0; k < int(n_steps); ++k) {
    const double t = k * dt;
    water.advance(model, t, 0.5 * dt);
    for (std::size_t i : source)
      model.set_enthalpy(i, model.enthalpy()[i] + 0.5 * q_L * dt / (double(source.size()) * model.volume()[i]));
    conduction.advance(model, t, dt);
    water.advance(model, t + 0.5 * dt, 0.5 * dt);
    model.apply_boundaries(t + dt);
  }
  // The nearest particle to each point, compared at its own position.
  std::vector<double> errors;
  for (const auto& [name, point] :
       {std::pair{"upstream", Vec<2>(-5.0, 0.0)}, std::pair{"downstream", Vec<2>(5.0, 0.0)},
        std::pair{"across", Vec<2>(0.0, 5.0)}, std::pair{"far downstream", Vec<2>(10.0, 0.0)}}) {
    std::size_t nearest = 0;
    for (std::size_t i = 1; i < cloud.n_free; ++i)
      if ((cloud.position[i] - point).norm() < (cloud.position[nearest] - point).norm()) nearest = i;
    const double exact = exact_rise(cloud.position[nearest], years), got = model.temperature()[nearest];
    errors.push_back(got / exact - 1.0);
    log += fmt::format("s {} m, {} ({:.2f}, {:.2f}) m: {:.5f} K against {:.5f} K ({:+.2f} %)\n", s, name,
                       cloud.position[nearest][0], cloud.position[nearest][1], got, exact, 100.0 * errors.back());
  }
  return errors;
}

}  // namespace

TEST_CASE("A line source in a Darcy flow against the moving line source solution",
          "[freezing][groundwater][advection][verification]") {
  std::string log;
  const auto coarse = line_source_errors(1.0, log), fine = line_source_errors(0.5, log);
  INFO(log);
  double worst_coarse = 0.0, worst_fine = 0.0;
  for (std::size_t k = 0; k < fine.size(); ++k) {
    CHECK(std::abs(fine[k]) < 0.02);
    worst_coarse = std::max(worst_coarse, std::abs(coarse[k]));
    worst_fine = std::max(worst_fine, std::abs(fine[k]));
  }
  CHECK(worst_fine < worst_coarse);  // converging with the spacing
}
