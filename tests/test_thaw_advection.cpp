// Story: Neumann's thaw with advection (Kurylyk et al. 2014; InterFrost
// TH1): frozen saturated sand (porosity 0.35) at -2 C, its surface x = 0
// held at +4 C from t = 0, water entering there at +4 C and flowing through
// thawed and frozen ground alike at a Darcy velocity of 10 or 100 m/yr (the
// benchmark's constant velocity: permeability law "constant"), 3 m to an
// outlet face that conducts no heat. Volumetric properties from the
// constituents: thawed k = 2.16, C = 2.902e6; frozen k = 2.70,
// C = 2.101e6; latent heat 0.35 x 920 x 334000 = 1.0755e8 J/m3.
// References:
//  - the thaw front of the same problem solved sharply by front fixing
//    (thaw_reference.hpp), computed here; checked against Neumann's exact
//    solution without flow (1e-4) and against itself on twice the nodes;
//  - every front within 1 % of it at the finest spacing (1 cm), the error
//    falling from 4 to 1 cm.
// The paper's own solution for this case (Lunardini's) is approximate, its
// error growing with the Stefan number (Kurylyk et al. 2014); the sharp
// solve is the exact answer of the equations it approximates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <memory>

#include "freezing/groundwater_flow.hpp"
#include "project/project.hpp"
#include "support.hpp"
#include "thaw_reference.hpp"

using namespace frostwall;

namespace {

constexpr double day = 86400.0, year = 365.25 * day;
constexpr double length = 3.0, K = 1e-5;  // m, m/s

test::ThawProblem sand(double darcy_m_per_year) {
  return {2.16, 2.902e6, 2.70, 2.101e6, 1.0755e8, 1000.0 * 4182.0 * darcy_m_per_year / year, 4.0, 0.0, -2.0, length};
}

// The strip two rows high, heads at both ends for the velocity asked.
project::Project strip(double dx, double darcy_m_per_year, double end_s) {
  const double head = darcy_m_per_year / year * length / K;
  const std::string text = fmt::format(R"({{
    "name": "thaw with advection",
    "geometry": {{ "type": "rectangle", "width": {}, "height": {}, "boundaries": {{
      "left": {{ "temperature": 4.0, "head": {} }}, "right": {{ "head": 0.0 }},
      "top": "adiabatic", "bottom": "adiabatic" }} }},
    "soil": {{ "name": "sand", "density": 2000, "latent_heat": 53775, "freezing_point": 0,
      "unfrozen": {{ "conductivity": 2.16, "heat_capacity": 1451 }},
      "frozen": {{ "conductivity": 2.70, "heat_capacity": 1050.5 }} }},
    "domain": {{ "initial_temperature": -2.0 }},
    "groundwater": {{ "hydraulic_conductivity": {}, "porosity": 0.35, "permeability_law": {{ "model": "constant" }},
      "water": {{ "density": 1000, "heat_capacity": 4182 }} }},
    "time": {{ "end": {}, "unit": "s", "snapshots": [{}] }},
    "numerics": {}, "output": {{ "directory": "unused" }} }})",
                                       length, 2 * dx, head, K, end_s, end_s,
                                       test::numerics(dx, "renormalised", "implicit"));
  return project::parse_project(text);
}

// The thawed depth: the free particles' liquid volume per unit height, from
// the held face's row (its cell ends half a spacing in).
double thawed_depth(const freezing::Model& m, double dx) {
  const auto& f = m.model->liquid_fraction();
  const auto& volume = m.particles().volume;
  double liquid = 0.0;
  for (std::size_t i = 0; i < m.model->free_count(); ++i) liquid += f[i] * volume[i];
  return 0.5 * dx + liquid / (2 * dx);
}

// Largest relative error of the front at the three times against `exact`.
double front_error(double dx, double darcy, const std::vector<double>& times, const std::vector<double>& exact) {
  const auto p = strip(dx, darcy, times.back());
  auto m = freezing::build_model(p);
  m.integrator = std::make_unique<freezing::GroundwaterFlow>(p, m);  // as the run wraps it
  double worst = 0.0;
  test::march(m, times,
              [&](std::size_t k) { worst = std::max(worst, std::abs(thawed_depth(m, dx) - exact[k]) / exact[k]); });
  return worst;
}

}  // namespace

TEST_CASE("The sharp thaw reference: Neumann's solution without flow, and converged",
          "[freezing][verification][thaw_advection]") {
  auto still = sand(0.0);
  still.length = 10.0;  // the far end undisturbed to day 10
  const std::vector<double> times{2.5 * day, 5 * day, 10 * day};
  const double lambda = test::neumann_lambda(still);
  const auto s = test::thaw_fronts(still, times, 200, 250);
  for (std::size_t k = 0; k < times.size(); ++k) CHECK(s[k] == Approx(2 * lambda * std::sqrt(times[k])).epsilon(1e-4));
  for (double darcy : {10.0, 100.0}) {
    const auto coarse = test::thaw_fronts(sand(darcy), times, 200, 250);
    const auto fine = test::thaw_fronts(sand(darcy), times, 400, 250);
    for (std::size_t k = 0; k < times.size(); ++k) CHECK(coarse[k] == Approx(fine[k]).epsilon(1e-4));
  }
}

TEST_CASE("Thaw with advection at 10 and 100 m/yr: fronts within 1 % of the sharp solution",
          "[freezing][verification][thaw_advection][groundwater]") {
  for (double darcy : {10.0, 100.0}) {
    const double end = darcy < 50 ? 10 * day : 1 * day;
    const std::vector<double> times{end / 4, end / 2, end};
    const auto exact = test::thaw_fronts(sand(darcy), times, 200, 250);
    std::vector<double> errors;
    for (double dx : {0.04, 0.02, 0.01}) errors.push_back(front_error(dx, darcy, times, exact));
    fmt::print("\nThaw with advection at {} m/yr: fronts {:.4f} {:.4f} {:.4f} m on days {:g} {:g} {:g}; "
               "worst error {:.3f} / {:.3f} / {:.3f} % at 4 / 2 / 1 cm\n",
               darcy, exact[0], exact[1], exact[2], times[0] / day, times[1] / day, times[2] / day, 100 * errors[0],
               100 * errors[1], 100 * errors[2]);
    CHECK(errors[2] < 0.01);
    CHECK(errors[2] < errors[0]);
  }
}
