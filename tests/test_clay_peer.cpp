// Story: the single ring in clay (26 pipes at -20 C on a 5 m ring, clay at
// 15 C), its pore water freezing along Anderson and Tice's power law, and
// the same clay freezing at 0 C. Reference: the finite-element peer
// (bench/peer/clay_ring.edp: FreeFem++, P1, lumped mass, backward Euler,
// semismooth Newton on the enthalpy with the Kirchhoff variable; its own
// closed-form enthalpy of the curve and its own closure path search),
// converged over three meshes and three steps by bench/clay_peer.py and
// stored with its uncertainty in bench/peer/clay_ring_converged.json.
// Tolerance: the shipped projects at 2 cm close within 1 % of it.
#include <catch2/catch.hpp>

#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "paths.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"

using namespace frostwall;

TEST_CASE("The clay shaft closes within 1 % of the finite-element peer, power-law curve and step",
          "[freezing][verification][clay_peer]") {
  std::ifstream in(std::filesystem::path(FROSTWALL_SOURCE_DIR) / "bench" / "peer" / "clay_ring_converged.json");
  const auto peer = nlohmann::json::parse(in);
  for (const auto& [name, law] :
       {std::pair{"single_ring_clay_power.json", "power"}, {"single_ring_clay.json", "step"}}) {
    test::TempDir dir("clay_peer");
    test::run_shipped(name,
                      {{"numerics", {{"spacing", 0.02}, {"error_estimate", false}}},
                       {"time", {{"end", 20}, {"unit", "d"}, {"snapshots", {20}}}},
                       {"output", {{"vtk", false}, {"report", false}}}},
                      dir.path);
    std::ifstream s_in(dir.path / "summary.json");
    const auto s = nlohmann::json::parse(s_in);
    const double day = s["closure_time_days"].get<double>(), reference = peer[law]["closure_day"].get<double>();
    fmt::print("\nClay shaft ({}), 2 cm: closure {:.3f} d, the finite-element peer {:.3f} +- {:.3f} d ({:+.2f} %)\n",
               law, day, reference, peer[law]["uncertainty_day"].get<double>(), 100 * (day / reference - 1));
    CHECK(std::abs(day / reference - 1) < 0.01);
  }
}
