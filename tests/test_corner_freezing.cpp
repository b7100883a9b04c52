// Story: the PD paper's corner freezing (section 3.1), shipped as
// projects/corner_freezing_L025.json and _L1.json and run as a user runs
// them (run_project, summary.json). A 1.5 m square of a unit material at
// 1.3, freezing at 1.0, cooled to 0 on the left and bottom faces. Far from
// the corner (the lines y = 1.2 and x = 1.2, 1.2 m from the other face)
// each front is the 1-D Neumann solution X = 2 lambda sqrt(t), lambda from
// the transcendental equation for the given latent heat (computed here by
// bisection; 0.70766 for L = 0.25, 0.52026 for L = 1). Tolerance: 1 % at
// the default spacing (the acceptance tolerance), and the error must fall as the
// spacing halves (it is first order: the front is read where the liquid
// fraction crosses 0.5). The diagonal front (the corner freezes ahead of
// both faces) is reported and must lie beyond sqrt(2) X.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using nlohmann::json;

namespace {

double neumann_lambda(double latent_heat) {  // T0 = 0, Tf = 1, Ti = 1.3, unit properties
  auto g = [&](double l) {
    return std::erf(l) * std::exp(l * l) * (l * latent_heat * std::sqrt(M_PI) + 0.3 * std::exp(-l * l) / std::erfc(l)) -
           1.0;
  };
  double a = 1e-6, b = 5.0;
  for (int k = 0; k < 200; ++k) {
    const double c = 0.5 * (a + b);
    (g(a) * g(c) <= 0 ? b : a) = c;
  }
  return 0.5 * (a + b);
}

struct Fronts {
  double edge = 0.0, edge_x = 0.0, diagonal = 0.0;  // at t = 0.1
};

Fronts run_corner(const std::string& project, const json& numerics) {
  test::TempDir dir("frostwall-corner");
  auto p = test::shipped_project(
      project, {{"numerics", numerics},
                {"output", {{"directory", (dir.path / "out").string()}, {"vtk", false}, {"report", false}}}});
  run::run_project(p, {});
  std::ifstream in(dir.path / "out" / "summary.json");
  const json s = json::parse(in);
  Fronts f;
  for (const auto& e : s["front_along"]) {
    if (e["t"] != 0.1) continue;
    REQUIRE(e["distance"].is_number());
    if (e["from"] == json({0.0, 1.2})) f.edge = e["distance"];
    if (e["from"] == json({1.2, 0.0})) f.edge_x = e["distance"];
    if (e["from"] == json({0.0, 0.0})) f.diagonal = e["distance"];
  }
  CHECK(s["run"]["method"] == "pd");
  CHECK(s["monitoring"]["corner"].size() >= 200);
  return f;
}

}  // namespace

TEST_CASE("Corner freezing (PD): the front far from the corner is Neumann's", "[mechanics][pd][verification][corner]") {
  for (const auto& [project, L] :
       {std::pair{"corner_freezing_L025.json", 0.25}, std::pair{"corner_freezing_L1.json", 1.0}}) {
    const double exact = 2.0 * neumann_lambda(L) * std::sqrt(0.1);
    std::vector<double> spacings{0.03, 0.015};
    std::vector<double> errors;
    for (double dx : spacings)
      errors.push_back(run_corner(project, {{"method", "pd"}, {"spacing", dx}}).edge / exact - 1.0);
    const Fronts shipped = run_corner(project, json::object());  // the project as shipped (default spacing 7.5 mm)
    fmt::print("\nCorner freezing L = {}: lambda {:.5f}, exact front at t = 0.1 {:.5f}; PD front on y = 1.2: "
               "3 cm {:+.3f} %, 1.5 cm {:+.3f} %, default (7.5 mm) {:+.3f} % (x = 1.2: {:+.3f} %); diagonal {:.4f} "
               "(sqrt 2 X = {:.4f})\n",
               L, neumann_lambda(L), exact, 100 * errors[0], 100 * errors[1], 100 * (shipped.edge / exact - 1.0),
               100 * (shipped.edge_x / exact - 1.0), shipped.diagonal, std::sqrt(2.0) * exact);
    CHECK(std::abs(shipped.edge / exact - 1.0) <= 0.01);
    CHECK(std::abs(shipped.edge_x - shipped.edge) < 1e-9);  // the square's symmetry
    CHECK(std::abs(errors[1]) < std::abs(errors[0]));
    CHECK(std::abs(shipped.edge / exact - 1.0) < std::abs(errors[1]));
    CHECK(shipped.diagonal > std::sqrt(2.0) * exact);
  }
}
