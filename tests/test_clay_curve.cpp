// Story: clay that keeps unfrozen water (projects/single_ring_clay_power.json:
// Anderson and Tice's power law, 0.05 theta^-0.5 of 0.189 kg per kg of
// solid). One of its pipes alone at the centre of a 1.2 m disc at 15 C, the
// far edge held at 15 C, ten days. Reference: the 1-D radial finite-volume
// solution of the same enthalpy equations and the same curve
// (tests/radial_reference.hpp: its own grid, time steps and Newton
// iteration on the curve), at 1 mm. Checks: the frozen radius (half the
// water ice) within 1 % at 1 cm, and the error falls at every halving from
// 4 cm.
#include <catch2/catch.hpp>

#include <fmt/core.h>

#include "post/isoline.hpp"
#include "radial_reference.hpp"
#include "support.hpp"

using namespace frostwall;
using nlohmann::json;

namespace {

double sph_frozen_radius(const project::Project& shipped, double spacing, double days) {
  auto m = freezing::build_model(shipped);
  REQUIRE(m.shaft->wedge.mirror_count == 0);
  test::march(m, {days * 86400.0}, [](std::size_t) {});
  const auto lines = post::isolines(m.particles().position, m.model->liquid_fraction(), 0.5, 3 * spacing);
  REQUIRE(lines.size() == 1);
  double sum = 0.0;
  for (const auto& x : lines[0].points) sum += x.norm();
  return sum / lines[0].points.size();
}

}  // namespace

TEST_CASE("One pipe in clay with a power-law freezing curve against the radial solution",
          "[freezing][verification][freezing_curve]") {
  const double days = 10.0;
  auto patch = [&](double spacing) {
    return json{
        {"layout", {{"pattern", "pipes"}, {"pipes", json::array({{{"x", 0.0}, {"y", 0.0}}})}, {"outer_ring", nullptr}}},
        {"shaft", nullptr},
        {"domain", {{"outer_radius", 1.2}}},
        {"design", nullptr},
        {"numerics", {{"spacing", spacing}, {"placement", "lattice"}}},
        {"time", {{"end", days}, {"unit", "d"}, {"snapshots", json::array({days})}}}};
  };
  const auto coarse_project = test::shipped_project("single_ring_clay_power.json", patch(0.04));
  REQUIRE(coarse_project.soil.freezing_curve.model == project::CurveModel::power);
  test::RadialProblem problem{coarse_project.soil, 0.0635, 1.2, 15.0, -20.0, 15.0};
  test::RadialReference reference(problem, 0.001);
  reference.advance_to(days * 86400.0);
  const double exact = reference.frozen_radius();
  const double coarse = sph_frozen_radius(coarse_project, 0.04, days);
  const double fine = sph_frozen_radius(test::shipped_project("single_ring_clay_power.json", patch(0.02)), 0.02, days);
  const double finest =
      sph_frozen_radius(test::shipped_project("single_ring_clay_power.json", patch(0.01)), 0.01, days);
  fmt::print("\nOne pipe in clay, power-law curve, day 10: radial FV {:.4f} m; SPH 4 cm {:.4f}, 2 cm {:.4f}, "
             "1 cm {:.4f} m\n",
             exact, coarse, fine, finest);
  CHECK(std::abs(finest - exact) < 0.01 * exact);
  CHECK(std::abs(finest - exact) < std::abs(fine - exact));
  CHECK(std::abs(fine - exact) < std::abs(coarse - exact));
}
