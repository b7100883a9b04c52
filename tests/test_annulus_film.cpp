// The brine film from the annulus flow (design/annulus_film.hpp): hand
// values of the laminar and the Gnielinski film, the transitional band's
// continuity at both ends, and a project that takes its h from the flow.
#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "design/annulus_film.hpp"
#include "cli.hpp"

using namespace frostwall::design;

namespace {
// A CaCl2 brine of about 30 % near -30 degC, illustrative round values.
const BrineProperties brine{1290.0, 0.0098, 0.52, 2700.0};
Annulus annulus(double flow_m3_per_h) { return {0.0603, 0.1143, flow_m3_per_h / 3600.0, brine}; }
}  // namespace

TEST_CASE("Annulus film: laminar Nu 4.9, Gnielinski turbulent, the band between continuous", "[freezing][brine]") {
  // Hand values: D_h = 0.054 m, area = pi/4 (0.1143^2 - 0.0603^2) = 7.4051e-3 m2,
  // 1.5 m3/h: v = 0.05627 m/s, Re = 1290 * 0.05627 * 0.054 / 0.0098 = 400.0,
  // Pr = 0.0098 * 2700 / 0.52 = 50.885; h = 4.9 * 0.52 / 0.054 = 47.19 on the
  // inner wall, 47.19 * 0.1143 / 0.127 = 42.47 on the outer one.
  const auto lam = annulus_film(annulus(1.5), 0.127);
  CHECK(lam.regime == FlowRegime::laminar);
  CHECK(lam.reynolds == Approx(399.96).epsilon(1e-4));
  CHECK(lam.prandtl == Approx(50.885).epsilon(1e-4));
  CHECK(lam.h_inner == Approx(47.185).epsilon(1e-4));
  CHECK(lam.h == Approx(42.467).epsilon(1e-4));
  // Gnielinski by hand: Re = 1e5, Pr = 7: f = (0.79 ln 1e5 - 1.64)^-2 = 0.018098,
  // Nu = 599.07; against Dittus-Boelter's 0.023 Re^0.8 Pr^0.4 = 500.7 (within 20 %).
  CHECK(gnielinski_nusselt(1e5, 7.0) == Approx(599.07).epsilon(1e-4));
  CHECK(gnielinski_nusselt(1e5, 7.0) == Approx(0.023 * std::pow(1e5, 0.8) * std::pow(7.0, 0.4)).epsilon(0.2));
  CHECK(gnielinski_nusselt(2e4, 20.0) == Approx(220.88).epsilon(1e-4));
  // The transitional band joins both ends; more flow, a better film.
  const double per_Re = 30.0 / 7999.23;  // m3/h per unit of Re at these properties
  const auto at = [&](double Re) { return annulus_film(annulus(Re * per_Re), 0.127); };
  CHECK(at(2299.0).nusselt == Approx(4.9).epsilon(1e-9));
  CHECK(at(2300.1).regime == FlowRegime::transitional);
  CHECK(at(2300.1).nusselt == Approx(4.9).epsilon(1e-3));
  CHECK(at(9999.0).nusselt == Approx(at(10001.0).nusselt).epsilon(1e-3));
  CHECK(at(10001.0).regime == FlowRegime::turbulent);
  double previous = 0.0;
  for (double Re : {500.0, 2500.0, 5000.0, 9000.0, 12000.0, 50000.0}) {
    CHECK(at(Re).h > previous - 1e-12);
    previous = at(Re).h;
  }
}

TEST_CASE("A brine pipe may take its film from the annulus flow: the run uses that h and reports the flow",
          "[freezing][brine][cli]") {
  nlohmann::json p = {
      {"name", "brine film from the flow"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 0.8}, {"count", 6}, {"start_angle_deg", 0.0}}}}},
      {"pipe",
       {{"diameter", 0.127},
        {"boundary", "brine"},
        {"brine_temperature", -25.0},
        {"annulus",
         {{"inner_diameter", 0.0603},
          {"outer_diameter", 0.1143},
          {"flow_m3_per_h", 1.5},
          {"brine", {{"density", 1290}, {"viscosity", 0.0098}, {"conductivity", 0.52}, {"heat_capacity", 2700}}}}}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 2.5}, {"initial_temperature", 10.0}, {"far_field", {{"temperature", 10.0}}}}},
      {"time", {{"end", 4}, {"unit", "d"}, {"snapshots", {4}}}},
      {"numerics", {{"placement", "lattice"}, {"spacing", 0.05}}},
      {"output", {{"directory", "out"}, {"vtk", false}, {"report", false}}}};
  const auto s = frostwall::test::run_project(p);
  CHECK(s["brine"]["heat_transfer_coefficient"].get<double>() == Approx(42.467).epsilon(1e-4));
  CHECK(s["brine"]["annulus"]["regime"] == "laminar");
  // A laminar film this poor holds the wall several kelvin above the brine.
  CHECK(s["brine"]["series"].back()[1].get<double>() > -25.0 + 2.0);
}
