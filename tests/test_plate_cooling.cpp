// Story: the PD paper's plate (section 3.2), shipped as
// projects/plate_cooling.json and run as a user runs it. A 1 cm square at
// 10 C is cooled to 1 C on its top and right edges, rests on rollers on the
// left and bottom. Checks:
//  1. a classical finite-element solution written here (tests/plate_fe.hpp:
//     P1, backward Euler, plane strain) converges in mesh and step;
//  2. the PD run (thermal bonds + bond-based mechanics, staggered, ADR) comes
//     within 2 % of the FE peak |u| at A (1 cm, 1 cm) and B (1 cm, 0.5 cm) at
//     t = 50, 100 and 200 s (CI: 0.2 mm spacing; the paper's 0.1 mm in
//     bench/, see README);
//  3. at steady state (run long) u = -(1 + nu) alpha 9 K (x, y) within 1 %.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>

#include "plate_fe.hpp"
#include "run/run_project.hpp"
#include "support.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using nlohmann::json;

namespace {

double magnitude(const std::array<double, 2>& u) { return std::hypot(u[0], u[1]); }

// |u| at A, B, C at the given times from a PD run of the shipped plate.
std::vector<std::array<double, 3>> pd_plate(double spacing, double end, const std::vector<double>& times) {
  test::TempDir dir("frostwall-plate");
  auto p = test::shipped_project(
      "plate_cooling.json",
      {{"numerics", {{"method", "pd"}, {"spacing", spacing}}},
       {"time", {{"end", end}, {"unit", "s"}, {"snapshots", times}}},
       {"output", {{"directory", (dir.path / "out").string()}, {"vtk", false}, {"report", false}}}});
  run::run_project(p, {});
  std::ifstream in(dir.path / "out" / "summary.json");
  const json s = json::parse(in);
  std::vector<std::array<double, 3>> out;
  for (double t : times) {
    std::array<double, 3> row{};
    int k = 0;
    for (const char* name : {"A", "B", "C"}) {
      for (const auto& r : s["monitoring_solid"][name])
        if (std::abs(r[0].get<double>() - t) < 1e-9) row[k] = std::hypot(r[1].get<double>(), r[2].get<double>());
      ++k;
    }
    out.push_back(row);
  }
  CHECK(s["run"]["mechanics"]["unconverged_relaxations"] == 0);
  return out;
}

}  // namespace

TEST_CASE("Plate cooling: the finite-element reference converges", "[pd][mechanics][verification]") {
  const std::vector<double> times{50, 100, 200};
  const auto coarse = test::plate_fe(20, 0.5, times), fine = test::plate_fe(40, 0.25, times),
             finer = test::plate_fe(80, 0.125, times);
  fmt::print("\nPlate FE reference |u| at A (m): mesh 20 / 40 / 80 (dt 0.5 / 0.25 / 0.125 s)\n");
  for (std::size_t k = 0; k < times.size(); ++k) {
    fmt::print("  t = {:3.0f} s: {:.5e}  {:.5e}  {:.5e}\n", times[k], magnitude(coarse.A[k]), magnitude(fine.A[k]),
               magnitude(finer.A[k]));
    const double e1 = std::abs(magnitude(coarse.A[k]) - magnitude(finer.A[k])),
                 e2 = std::abs(magnitude(fine.A[k]) - magnitude(finer.A[k]));
    CHECK(e2 < e1);
    CHECK(e2 < 2e-3 * magnitude(finer.A[k]));
  }
}

TEST_CASE("Plate cooling: PD within 2 % of finite elements at A and B", "[pd][mechanics][verification]") {
  const std::vector<double> times{50, 100, 200};
  const auto fe = test::plate_fe(80, 0.125, times);
  const auto pd = pd_plate(0.0002, 200, times);
  fmt::print("\nPlate cooling, PD (0.2 mm) vs FE (80 x 80, dt 0.125 s), |u| in m:\n");
  for (std::size_t k = 0; k < times.size(); ++k) {
    const double eA = pd[k][0] / magnitude(fe.A[k]) - 1.0, eB = pd[k][1] / magnitude(fe.B[k]) - 1.0,
                 eC = pd[k][2] / magnitude(fe.C[k]) - 1.0;
    fmt::print("  t = {:3.0f} s: A {:.4e} vs {:.4e} ({:+.2f} %), B {:.4e} vs {:.4e} ({:+.2f} %), C {:+.2f} %\n",
               times[k], pd[k][0], magnitude(fe.A[k]), 100 * eA, pd[k][1], magnitude(fe.B[k]), 100 * eB, 100 * eC);
    CHECK(std::abs(eA) < 0.02);
    CHECK(std::abs(eB) < 0.02);
  }
}

TEST_CASE("Plate cooling: steady state is the exact free contraction", "[pd][mechanics][verification]") {
  // 5000 s is 16 diffusion times: the plate is at 1 C throughout.
  const auto pd = pd_plate(0.0005, 5000, {5000});
  const double exact = (1.0 + 0.25) * 1.8e-5 * 9.0;  // |u| / |x|
  const double A = exact * 0.01 * std::sqrt(2.0), B = exact * std::hypot(0.01, 0.005),
               C = exact * 0.005 * std::sqrt(2.0);
  fmt::print("\nPlate at steady state (0.5 mm): |u| A {:.5e} (exact {:.5e}), B {:.5e} ({:.5e}), C {:.5e} ({:.5e})\n",
             pd[0][0], A, pd[0][1], B, pd[0][2], C);
  CHECK(pd[0][0] == Approx(A).epsilon(0.01));
  CHECK(pd[0][1] == Approx(B).epsilon(0.01));
  CHECK(pd[0][2] == Approx(C).epsilon(0.01));
}
