// The thickness a frozen shaft wall needs (design/wall_strength.hpp)
// against hand values computed from the formulas as written out there,
// and the invariants a designer relies on: a colder (stronger) wall needs
// less thickness, Mohr-Coulomb without friction is the Tresca limit with
// s = 2 c, and a strength table must not weaken as the soil gets colder.
#include <catch2/catch.hpp>
#include <cmath>

#include "design/wall_strength.hpp"

using namespace frostwall::design;

TEST_CASE("Wall thickness formulas match hand values", "[freezing][design]") {
  // a = 3.5 m, P = 2.6 MPa, s = 5 MPa: P / s = 0.52.
  CHECK(required_thickness(Formula::domke, 3.5, 2.6, 5.0).value() == Approx(2.70).margin(0.005));
  CHECK(required_thickness(Formula::plastic_tresca, 3.5, 2.6, 5.0).value() == Approx(2.39).margin(0.005));
  CHECK(required_thickness(Formula::lame_mises, 3.5, 2.6, 5.0).value() == Approx(7.605).margin(0.005));
  CHECK_FALSE(required_thickness(Formula::lame_tresca, 3.5, 2.6, 5.0).has_value());  // s < 2 P
  // P = 1.3 MPa, s = 8 MPa: 0.38, 0.62, 0.63, 0.76 m.
  CHECK(required_thickness(Formula::domke, 3.5, 1.3, 8.0).value() == Approx(0.38).margin(0.005));
  CHECK(required_thickness(Formula::plastic_tresca, 3.5, 1.3, 8.0).value() == Approx(0.62).margin(0.005));
  CHECK(required_thickness(Formula::lame_mises, 3.5, 1.3, 8.0).value() == Approx(0.63).margin(0.005));
  CHECK(required_thickness(Formula::lame_tresca, 3.5, 1.3, 8.0).value() == Approx(0.76).margin(0.005));
  // Without cohesion and friction given, Mohr-Coulomb has no value.
  CHECK_FALSE(required_thickness(Formula::plastic_mohr_coulomb, 3.5, 1.3, 8.0).has_value());
}

TEST_CASE("The Lame walls carry the pressure they were sized for", "[freezing][design]") {
  // Elastic thick cylinder, outer pressure P, inner face free: the hoop
  // stress at the inner face is 2 P b^2 / (b^2 - a^2), the radial one 0.
  // Tresca's stress difference there is the hoop stress; von Mises' stress
  // in plane strain with an incompressible soil (sigma_z the mean of the
  // other two) is sqrt(3)/2 of it. At the thickness found, each equals s.
  const double a = 3.5, P = 1.3, s = 8.0;
  auto hoop = [&](Formula f) {
    const double b = a + required_thickness(f, a, P, s).value();
    return 2.0 * P * b * b / (b * b - a * a);
  };
  CHECK(hoop(Formula::lame_tresca) == Approx(s).epsilon(1e-12));
  CHECK(std::sqrt(3.0) / 2.0 * hoop(Formula::lame_mises) == Approx(s).epsilon(1e-12));
}

TEST_CASE("A colder wall needs less thickness, on every formula", "[freezing][design]") {
  const auto law = StrengthLaw::power(1.5, 0.8, 0.9);  // illustrative
  const MohrCoulomb mc_warm{0.5 * 0.5 * law.at(-5.0), 15.0}, mc_cold{0.5 * 0.5 * law.at(-15.0), 15.0};
  for (Formula f : all_formulas) {
    INFO(name(f));
    const double s_warm = 0.5 * law.at(-5.0), s_cold = 0.5 * law.at(-15.0);
    const auto warm = required_thickness(f, 3.5, 1.0, s_warm, &mc_warm),
               cold = required_thickness(f, 3.5, 1.0, s_cold, &mc_cold);
    REQUIRE(warm.has_value());
    REQUIRE(cold.has_value());
    CHECK(*cold < *warm);
  }
}

TEST_CASE("Mohr-Coulomb's plastic limit: Tresca without friction, thinner with it", "[freezing][design]") {
  const double a = 3.5, P = 2.0, c = 1.5;
  const MohrCoulomb frictionless{c, 0.0}, rough{c, 20.0};
  CHECK(required_thickness(Formula::plastic_mohr_coulomb, a, P, 1.0, &frictionless).value() ==
        Approx(required_thickness(Formula::plastic_tresca, a, P, 2.0 * c).value()).epsilon(1e-12));
  const MohrCoulomb nearly{c, 1e-6};
  CHECK(required_thickness(Formula::plastic_mohr_coulomb, a, P, 1.0, &nearly).value() ==
        Approx(required_thickness(Formula::plastic_tresca, a, P, 2.0 * c).value()).epsilon(1e-6));
  // Friction adds strength as the confinement grows into the wall.
  CHECK(required_thickness(Formula::plastic_mohr_coulomb, a, P, 1.0, &rough).value() <
        required_thickness(Formula::plastic_tresca, a, P, 2.0 * c).value());
  // The limit it encodes: sigma_r(b) = P with sigma_r + sigma_c/(N-1) = C r^(N-1), sigma_r(a) = 0.
  const double sin_phi = std::sin(20.0 * M_PI / 180.0), N = (1 + sin_phi) / (1 - sin_phi);
  const double sigma_c = 2.0 * c * std::cos(20.0 * M_PI / 180.0) / (1 - sin_phi);
  const double b = a + required_thickness(Formula::plastic_mohr_coulomb, a, P, 1.0, &rough).value();
  CHECK(sigma_c / (N - 1.0) * (std::pow(b / a, N - 1.0) - 1.0) == Approx(P).epsilon(1e-12));
}

TEST_CASE("Strength laws: table, linear and power, and a table must not weaken as it gets colder",
          "[freezing][design]") {
  const auto table = StrengthLaw::table({{-20.0, 9.0}, {-2.0, 2.0}, {-10.0, 6.0}});
  CHECK(table.at(-10.0) == Approx(6.0));
  CHECK(table.at(-6.0) == Approx(4.0));   // halfway between -10 and -2
  CHECK(table.at(-30.0) == Approx(9.0));  // held at its ends
  CHECK(table.at(0.0) == Approx(2.0));
  CHECK(StrengthLaw::linear(1.0, 0.4).at(-10.0) == Approx(5.0));
  CHECK(StrengthLaw::power(1.0, 0.5, 2.0).at(-4.0) == Approx(9.0));
  CHECK(table_problem({{-20.0, 9.0}, {-2.0, 2.0}}).empty());
  CHECK(table_problem({{-20.0, 5.0}, {-10.0, 6.0}}) ==
        "strength must not fall as the soil gets colder: 5 MPa at -20 C, 6 MPa at -10 C");
  CHECK(table_problem({{-20.0, 5.0}}) == "needs at least two [T, sigma_c] points");
  CHECK(table_problem({{-20.0, 5.0}, {-10.0, -1.0}}) == "strength must be positive, got -1 MPa at -10 C");
}
