// Story: InterFrost TH2, the frozen inclusion (Grenier et al. 2018), at a
// 3 % head gradient, as shipped but on a 2 cm lattice: water at +5 C flows
// through sand round a square of ice and thaws it. References:
//  - PM1: the domain's coldest temperature rises above 0 C inside the 13
//    codes' range, 18.1-20.7 h (median 18.9 h);
//  - energy: the heat stored equals the heat brought through the faces
//    (conduction and water), to the coupled step's Newton tolerance;
//  - PM3 by hand: 0.37 x (3 - 0.95 / 9) m3/m liquid at the start (the
//    square's water 95 % ice at -5 C), 0.37 x 3 once all has thawed;
//  - the report names the curve and draws it;
//  - the flow once thawed: K dh / L x 1 m with K = k rho g / mu, the
//    straight head between the faces, within 1e-3.
#include <catch2/catch.hpp>

#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <iterator>
#include <string>
#include <nlohmann/json.hpp>

#include "shipped_run.hpp"
#include "temp_dir.hpp"

using namespace frostwall;

TEST_CASE("InterFrost TH2 at 3 %: the inclusion thaws inside the codes' range",
          "[freezing][verification][interfrost]") {
  test::TempDir dir("th2");
  test::run_shipped("interfrost_th2_3.json", {{"numerics", {{"spacing", 0.02}}}, {"output", {{"vtk", false}}}},
                    dir.path);
  std::ifstream in(dir.path / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);

  const double thaw = s["thaw_time"].get<double>();
  fmt::print("\nInterFrost TH2 at 3 %, 2 cm: the coldest ground above 0 C after {:.3f} h (codes 18.1-20.7 h)\n", thaw);
  CHECK(thaw > 18.1);
  CHECK(thaw < 20.7);

  const auto& balance = s["heat_balance"];
  double brought = 0.0, largest = 0.0;
  for (const auto& [face, heat] : balance["from_boundaries"].items()) {
    brought += heat.get<double>();
    largest = std::max(largest, std::abs(heat.get<double>()));
  }
  CHECK(std::abs(balance["stored_change"].get<double>() - brought) < 1e-4 * largest);

  const auto& rows = s["balance"];
  REQUIRE(rows.size() > 100);
  // The free particles' cells cover x from half a spacing off the held
  // left face (it lies on a row) to the right face: 3 - dx / 2 by 1 m.
  const double area = 3.0 - 0.5 * s["run"]["spacing"].get<double>();
  CHECK(rows.front()["time"].get<double>() == 0.0);
  CHECK(rows.front()["liquid_water_m3"].get<double>() == Approx(0.37 * (area - 0.95 / 9.0)).epsilon(1e-3));
  CHECK(rows.back()["liquid_water_m3"].get<double>() == Approx(0.37 * area).epsilon(1e-9));
  CHECK(rows.front()["min_temperature"].get<double>() == Approx(-5.0).margin(1e-9));
  // The heat leaving per metre (W, over hours) adds up to what the domain
  // lost: the rows' units and intervals.
  double lost = 0.0;
  for (std::size_t k = 1; k < rows.size(); ++k)
    lost += rows[k]["net_heat_out_W"].get<double>() * 3600.0 *
            (rows[k]["time"].get<double>() - rows[k - 1]["time"].get<double>());
  CHECK(-lost == Approx(balance["stored_change"].get<double>()).epsilon(1e-3));

  // The report names the curve and draws it.
  std::ifstream report_in(dir.path / "report.html");
  const std::string report((std::istreambuf_iterator<char>(report_in)), std::istreambuf_iterator<char>());
  CHECK(report.find("exponential, S_w = 0.050 + 0.950 exp(-((T - Tf)/0.500 K)²)") != std::string::npos);
  CHECK(report.find("The liquid share of the pore water as the solver holds it") != std::string::npos);

  const double K = 1.3e-10 * 1000 * 9.81 / 1.793e-3;
  // (The discrete flow's boundary error is first order: 3.6e-4 at 2 cm,
  // 1.8e-4 at 1 cm.)
  CHECK(s["groundwater"]["inflow_m2_per_s"].get<double>() == Approx(K * 0.09 / 3.0).epsilon(1e-3));
}
