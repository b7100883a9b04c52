// Story: a soil given by what it is made of, InterFrost TH2's sand
// (porosity 0.37; solid 2650 kg/m3, 835 J/(kg K), 9 W/(m K); water 1000,
// 4182, 0.6, latent heat 3.34e5 J/kg; ice 920, 2060, 2.14), saturated, the
// step freezing curve. Reference: the hand calculation per unit volume,
//   rho C unfrozen = 0.63 * 2650 * 835 + 0.37 * 1000 * 4182 = 2 941 372.5 J/(m3 K)
//   rho C frozen   = 0.63 * 2650 * 835 + 0.37 *  920 * 2060 = 2 095 256.5
//   latent heat    = 0.37 *  920 * 3.34e5                   = 1.136936e8 J/m3
//                    (the pore's mass when full of ice freezes)
//   k arithmetic   = 0.63 * 9 + 0.37 * 0.6 = 5.892; frozen 0.63 * 9 + 0.37 * 2.14 = 6.4618
//   k geometric    = 9^0.63 * 0.6^0.37 = 3.3937...; frozen 9^0.63 * 2.14^0.37 = 5.3437...
// and the soil's fields given the old way with those values load the same
// soil. Bad input names its path.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "project/project.hpp"
#include "soil_text.hpp"

using namespace frostwall;

namespace {

const std::string& th2 = testing::th2_constituents;
using testing::soil_of;

}  // namespace

TEST_CASE("A soil from its constituents: volumetric heat, latent heat and both mixing rules by hand",
          "[soil_constituents]") {
  const auto arithmetic = soil_of(th2 + "}");
  CHECK(arithmetic.density * arithmetic.unfrozen.heat_capacity == Approx(2941372.5).epsilon(1e-12));
  CHECK(arithmetic.density * arithmetic.frozen.heat_capacity == Approx(2095256.5).epsilon(1e-12));
  CHECK(arithmetic.density * arithmetic.latent_heat == Approx(1.136936e8).epsilon(1e-12));
  CHECK(arithmetic.unfrozen.conductivity[0] == Approx(5.892).epsilon(1e-12));
  CHECK(arithmetic.frozen.conductivity[1] == Approx(6.4618).epsilon(1e-12));
  CHECK(arithmetic.freezing_point == 0.0);

  const auto geometric = soil_of(th2 + R"(, "conductivity_mixing": "geometric" })");
  CHECK(geometric.unfrozen.conductivity[0] == Approx(std::exp(0.63 * std::log(9.0) + 0.37 * std::log(0.6))));
  CHECK(geometric.frozen.conductivity[0] == Approx(std::exp(0.63 * std::log(9.0) + 0.37 * std::log(2.14))));

  // The same soil given the old way.
  const double rho = 0.63 * 2650 + 0.37 * 1000;
  const auto old = soil_of(R"({ "density": )" + std::to_string(rho) + R"(,
      "unfrozen": { "conductivity": 5.892, "heat_capacity": )" +
                           std::to_string(2941372.5 / rho) + R"( },
      "frozen": { "conductivity": 6.4618, "heat_capacity": )" +
                           std::to_string(2095256.5 / rho) + R"( },
      "latent_heat": )" + std::to_string(1.136936e8 / rho) +
                           "}");
  CHECK(old.unfrozen.heat_capacity == Approx(arithmetic.unfrozen.heat_capacity).epsilon(1e-6));
  CHECK(old.latent_heat == Approx(arithmetic.latent_heat).epsilon(1e-6));

  try {
    soil_of(R"({ "porosity": 1.2, "density": 2000, "solid": { "density": 2650 }, "water": {}, "ice": {},
                 "conductivity_mixing": "harmonic" })");
    FAIL("bad constituents were accepted");
  } catch (const project::ProjectError& e) {
    const std::string text = e.what();
    for (const char* path :
         {"soil.porosity: must be below 1", "soil.density: computed from the constituents",
          "soil.solid.heat_capacity: required", "soil.water.latent_heat: required", "soil.conductivity_mixing:"}) {
      INFO(text);
      CHECK(text.find(path) != std::string::npos);
    }
  }
}
