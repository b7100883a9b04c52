// Ice blocks the pores on every permeability law. Each
// law is 1 in unfrozen ground, never rises as ice forms, falls by orders
// of magnitude by the time the pores are frozen (down to the floor), and
// matches a hand value; research codes have been seen to switch this
// coupling off silently, so a law that ignores ice fails here.
#include <catch2/catch.hpp>
#include <cmath>

#include "groundwater/permeability_law.hpp"

using namespace frostwall::groundwater;

TEST_CASE("Permeability falls as ice forms, on every law", "[freezing][groundwater][permeability]") {
  for (auto model : {PermeabilityModel::impedance, PermeabilityModel::kozeny_carman, PermeabilityModel::threshold}) {
    PermeabilityLaw law{model};
    INFO(law.name());
    CHECK(law.relative(1.0) == Approx(1.0));
    double previous = law.relative(1.0);
    for (int k = 1; k <= 100; ++k) {
      const double f = 1.0 - k / 100.0;  // ice forming: S_ice = k / 100
      const double now = law.relative(f);
      CHECK(now <= previous);
      CHECK(now >= law.floor);
      previous = now;
    }
    CHECK(law.relative(0.0) < 1e-3);  // frozen pores block the flow
    PermeabilityModel parsed{};
    REQUIRE(permeability_model_from_name(law.name(), parsed));
    CHECK(parsed == model);
  }
  // The benchmarks' water at a fixed velocity ignores ice, by name only
  // (and the run warns).
  PermeabilityLaw constant{PermeabilityModel::constant};
  CHECK(constant.relative(0.0) == 1.0);
  PermeabilityModel parsed{};
  REQUIRE(permeability_model_from_name("constant", parsed));
  CHECK(parsed == PermeabilityModel::constant);
  PermeabilityModel unknown{};
  CHECK_FALSE(permeability_model_from_name("cubic", unknown));
}

TEST_CASE("Permeability laws against hand values", "[freezing][groundwater][permeability]") {
  // Hansson et al.'s Omega = 7 at half the pore water frozen: 10^-3.5.
  PermeabilityLaw hansson{PermeabilityModel::impedance, 7.0};
  CHECK(hansson.relative(0.5) == Approx(std::pow(10.0, -3.5)).epsilon(1e-12));
  // InterFrost's Omega = 50 reaches the floor (1e-6) at S_ice = 0.12.
  PermeabilityLaw interfrost{PermeabilityModel::impedance, 50.0};
  CHECK(interfrost.relative(0.9) == Approx(1e-5).epsilon(1e-12));
  CHECK(interfrost.relative(0.8) == Approx(1e-6));
  // Kozeny-Carman, n = 0.4, half frozen: n_l = 0.2;
  // (0.008 / 0.64) / (0.064 / 0.36) = 0.0125 / 0.17778 = 0.0703125.
  PermeabilityLaw kc{PermeabilityModel::kozeny_carman};
  kc.porosity = 0.4;
  CHECK(kc.relative(0.5) == Approx(0.0703125).epsilon(1e-12));
  // Threshold at f_c = 0.1: open at 0.1, closed (the floor) just below.
  PermeabilityLaw step{PermeabilityModel::threshold};
  CHECK(step.relative(0.1) == 1.0);
  CHECK(step.relative(0.0999) == step.floor);
}
