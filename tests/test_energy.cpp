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

TEST_CASE("A time loop advanced in parts lands on each stop and, stopping at its snapshots, steps as in one run",
          "[freezing][energy][time_loop]") {
  // Invariants of the march: stops at the snapshots change no step (the
  // same fields bit for bit); a stop between them is landed on exactly, and
  // the heat through the boundaries still adds up to the change in storage.
  auto build = [] {
    return freezing::build_model(test::rectangle_project(
        1.0, 1.0,
        R"({ "left": { "temperature": -10.0 }, "right": "adiabatic", "top": "adiabatic", "bottom": "adiabatic" })",
        R"("sand")", 5.0, 4000.0, test::numerics(1.0 / 20, "renormalised", "rkl2")));
  };
  const std::vector<double> snapshots{1000.0, 4000.0};
  auto whole = build();
  thermal::run_time_loop(*whole.model, *whole.integrator, 4000.0, snapshots, {});
  auto parts = build();
  thermal::TimeLoop loop(*parts.model, *parts.integrator, 4000.0, snapshots, {});
  CHECK(loop.advance_to(1000.0) == 1000.0);
  CHECK_FALSE(loop.done());
  CHECK(loop.advance_to(1e9) == 4000.0);
  CHECK(loop.done());
  CHECK(parts.model->temperature() == whole.model->temperature());

  auto between = build();
  const double before = between.model->stored_heat();
  thermal::TimeLoop stops(*between.model, *between.integrator, 4000.0, snapshots, {});
  for (double stop : {333.0, 1000.0, 2718.0}) CHECK(stops.advance_to(stop) == stop);
  stops.advance_to(4000.0);
  double brought = 0.0;
  for (double q : stops.result().boundary_heat) brought += q;
  CHECK(between.model->stored_heat() - before == Approx(brought).epsilon(1e-9));
}
