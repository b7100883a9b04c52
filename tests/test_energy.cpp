// Story: energy bookkeeping. The pair flux is antisymmetric (mirror images
// included), so an insulated box conserves sum V_i H_i to round-off, even
// while half of it freezes. With a cooled face, what the box loses is what
// the boundary pairs carried out, step by step. Each integrator: forward
// Euler and RKL2 (a combination of explicit stages) to round-off; backward
// Euler to its Newton tolerance (1e-7 of the latent heat per particle and
// step, so 1e-9 of the box's heat over the run is the bound to expect).
#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

using namespace frostwall;

namespace {

// A 1 m square of sand over the time of 1000 explicit steps, each
// integrator at its own steps.
struct EnergyRun {
  double stored_before, stored_after, boundary_heat, scale;
};

EnergyRun run_box(const std::string& boundaries, double initial_hot, double initial_cold,
                  const std::string& integrator) {
  const double dx = 1.0 / 40;
  auto p = test::rectangle_project(1.0, 1.0, boundaries, R"("sand")", initial_hot, 1.0,
                                   test::numerics(dx, "renormalised", integrator));
  auto m = freezing::build_model(p);
  auto& model = *m.model;
  for (std::size_t i = 0; i < model.free_count(); ++i)
    if (m.particles().position[i][0] > 0.5) model.set_enthalpy(i, model.law().enthalpy(initial_cold));
  EnergyRun r{};
  r.stored_before = model.stored_heat();
  const double t_end = 1000 * 0.1 * m.h * m.h / model.law().max_diffusivity();
  for (double q : thermal::run_time_loop(model, *m.integrator, t_end, {t_end}, {}).boundary_heat) r.boundary_heat += q;
  r.stored_after = model.stored_heat();
  for (std::size_t i = 0; i < model.free_count(); ++i) r.scale += model.volume()[i] * std::abs(model.enthalpy()[i]);
  return r;
}

}  // namespace

TEST_CASE("Insulated box with a hot and a cold half conserves energy", "[freezing][verification][energy]") {
  const std::string integrator = GENERATE("explicit", "rkl2", "implicit");
  const auto r = run_box(R"({ "left": "adiabatic", "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
                         10.0, -10.0, integrator);
  const double drift = std::abs(r.stored_after - r.stored_before) / r.scale;
  fmt::print("\nInsulated box, {}: relative energy drift {:.2e}\n", integrator, drift);
  CHECK(drift < (integrator == "implicit" ? 1e-9 : 1e-12));
}

TEST_CASE("Cooled face: energy lost equals the boundary flux integrated in time", "[freezing][verification][energy]") {
  const std::string integrator = GENERATE("explicit", "rkl2", "implicit");
  const auto r =
      run_box(R"({ "left": { "temperature": -20 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
              10.0, 10.0, integrator);
  const double change = r.stored_after - r.stored_before;
  fmt::print("\nCooled face, {}: stored change {:.9e} J/m, boundary heat {:.9e} J/m\n", integrator, change,
             r.boundary_heat);
  CHECK(change < 0.0);
  CHECK(std::abs(change - r.boundary_heat) < 1e-6 * std::abs(change));
}
