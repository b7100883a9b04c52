// Story: the CFD-DEM engine's checks, each through the shipped
// project and the command line, against formulas written out here:
//  - check 1: one grain settles at its drag law's terminal velocity;
//  - check 2: a fixed bed's pressure drop is Ergun's, and the grains'
//    drag plus pressure-gradient force carries it;
//  - check 3: a free bed fluidises at Ergun's minimum fluidisation
//    velocity and then holds its buoyant weight;
//  - check 4: upward seepage heaves a quartz column at Terzaghi's
//    critical gradient;
//  - check 5: the fluid's mass balance in a run, and one rank against two.
#include <catch2/catch.hpp>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVariant.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "cli.hpp"
#include "temp_dir.hpp"
#include "paths.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const fs::path projects = fs::path(FROSTWALL_SOURCE_DIR) / "projects";
constexpr double g = 9.81;

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// Runs a project (edited by `edit`) in a scratch directory with its own
// packing cache; returns its summary.json.
json run_project(const frostwall::test::TempDir& dir, const std::string& name, const std::function<void(json&)>& edit,
                 const std::string& launcher = "") {
  json p = read_json(projects / (name + ".json"));
  p["output"]["directory"] = "out";
  if (edit) edit(p);
  std::ofstream(dir.path / "p.json") << p.dump(2);
  setenv("FROSTWALL_CACHE", (dir.path / "cache").c_str(), 1);
  frostwall::test::require_frostwall(dir.path, "run p.json", {launcher});
  return read_json(dir.path / "out" / "summary.json");
}

// Ergun (1952) on the superficial velocity U, written out anew.
double ergun(double mu, double rho, double e, double d, double U) {
  return 150.0 * mu * (1 - e) * (1 - e) * U / (e * e * e * d * d) + 1.75 * rho * (1 - e) * U * U / (e * e * e * d);
}

}  // namespace

TEST_CASE("CFD-DEM check 1: verify_settling, a quartz grain reaches the Dallavalle terminal velocity",
          "[cfd_dem][verification]") {
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_settling", {});
  const double d = 0.004, rho_p = 2650.0, rho = 1000.0, mu = 1e-3;
  auto excess = [&](double u) {
    const double Re = rho * u * d / mu, Cd = std::pow(0.63 + 4.8 / std::sqrt(Re), 2);
    return (rho_p - rho) * g * d * d * d * std::numbers::pi / 6.0 -
           0.5 * Cd * rho * std::numbers::pi * d * d / 4.0 * u * u;
  };
  double lo = 1e-6, hi = 10.0;
  for (int it = 0; it < 200; ++it) (excess(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  fmt::print("CFD-DEM settling: {:.4f} m/s, Dallavalle {:.4f} m/s\n", s["terminal_velocity_m_s"].get<double>(), lo);
  CHECK(s["terminal_velocity_m_s"].get<double>() == Approx(lo).epsilon(0.02));
  CHECK(s["settling"].size() > 100);
}

TEST_CASE("CFD-DEM check 2: verify_ergun, a fixed bed's pressure drop follows Ergun", "[cfd_dem][verification]") {
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_ergun", {});
  const double reference[] = {23.0, 115.1, 230.5};  // CFDEMcoupling's ErgunTestMPI, Pa
  REQUIRE(s["ergun"].size() == 3);
  for (int k = 0; k < 3; ++k) {
    const auto& e = s["ergun"][k];
    const double U = e["superficial_velocity"], eps = e["porosity"], L = e["bed_length"], dP = e["pressure_drop_Pa"];
    fmt::print("Ergun bed: U {:.4f} m/s, porosity {:.4f}, dP {:.2f} Pa (formula {:.2f}, CFDEMcoupling {:.1f}); "
               "grains carry {:.3f} of dP A\n",
               U, eps, dP, ergun(1.5e-3, 10.0, eps, 1e-3, U) * L, reference[k],
               e["fluid_force_on_grains_N"].get<double>() / e["pressure_drop_times_area_N"].get<double>());
    CHECK(eps == Approx(0.4513).margin(0.001));
    CHECK(dP == Approx(ergun(1.5e-3, 10.0, eps, 1e-3, U) * L).epsilon(0.05));
    CHECK(dP == Approx(reference[k]).epsilon(0.05));
    // Di Felice's drag plus -V grad p against the pressure drop: within 15 %.
    CHECK(e["fluid_force_on_grains_N"].get<double>() ==
          Approx(e["pressure_drop_times_area_N"].get<double>()).epsilon(0.15));
  }
}

TEST_CASE("CFD-DEM: Gidaspow's drag returns to the grains exactly the momentum the fixed bed's water loses",
          "[cfd_dem]") {
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_ergun", [](json& p) {
    p["forces"] = {"gidaspow_drag", "pressure_gradient", "buoyancy"};
  });
  for (const auto& e : s["ergun"])
    CHECK(e["fluid_force_on_grains_N"].get<double>() ==
          Approx(e["pressure_drop_times_area_N"].get<double>()).epsilon(1e-9));
}

TEST_CASE("CFD-DEM check 3: verify_fluidisation, a free bed lifts at Ergun's minimum fluidisation velocity",
          "[cfd_dem][verification]") {
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_fluidisation", {});
  const auto& f = s["minimum_fluidisation"];
  REQUIRE(f["velocity_m_s"].is_number());
  const double eps = f["porosity"], L = f["bed_length_m"], U_mf = f["velocity_m_s"];
  // The bed's buoyant weight per area, from the grains as given.
  const double grains = 480, volume = std::numbers::pi / 6.0 * 1e-9, area = 0.006 * 0.006;
  const double weight = grains * volume * (2000.0 - 10.0) * g / area;
  // Ergun's U_mf for this bed: dP(U) L = weight, by bisection.
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 200; ++it)
    (ergun(1.5e-3, 10.0, eps, 1e-3, 0.5 * (lo + hi)) * L < weight ? lo : hi) = 0.5 * (lo + hi);
  fmt::print(
      "fluidisation: porosity {:.4f}, U_mf {:.5f} m/s (Ergun {:.5f}, CFDEMcoupling 0.0145 at 0.4513), lift-off at "
      "{:.5f} m/s; plateau {:.1f} Pa, buoyant weight {:.1f} Pa\n",
      eps, U_mf, lo, f["lift_velocity_m_s"].get<double>(), f["plateau_pressure_drop_Pa"].get<double>(), weight);
  CHECK(f["buoyant_weight_Pa"].get<double>() == Approx(weight).epsilon(1e-6));
  CHECK(U_mf == Approx(lo).epsilon(0.10));
  CHECK(U_mf == Approx(0.0145).epsilon(0.10));
  CHECK(f["plateau_pressure_drop_Pa"].get<double>() == Approx(weight).epsilon(0.10));
  // Below U_mf the bed stays put: no lift-off before it.
  CHECK(f["lift_velocity_m_s"].get<double>() >= 0.95 * U_mf);
  // Refinement: on cells of 3 grain diameters (10 along the column, not
  // the shipped 20) the bed's surface smears over a coarser cell and the
  // plateau strays further from the buoyant weight.
  frostwall::test::TempDir coarse_dir;
  const json coarse = run_project(coarse_dir, "verify_fluidisation", [](json& p) { p["fluid"]["cells"] = {1, 1, 10}; });
  const double coarse_plateau = coarse["minimum_fluidisation"]["plateau_pressure_drop_Pa"];
  fmt::print("fluidisation plateau: {:.2f} Pa on 10 cells, {:.2f} Pa on 20; buoyant weight {:.2f} Pa\n", coarse_plateau,
             f["plateau_pressure_drop_Pa"].get<double>(), weight);
  CHECK(std::abs(f["plateau_pressure_drop_Pa"].get<double>() - weight) < std::abs(coarse_plateau - weight));
  // Check 5, mass: the water that enters leaves, cell by cell.
  const auto& m = s["mass_balance"];
  CHECK(m["largest_cell_imbalance_m3_s"].get<double>() < 1e-8 * m["largest_inflow_m3_s"].get<double>());
  CHECK(m["largest_inflow_minus_outflow_m3_s"].get<double>() < 1e-8 * m["largest_inflow_m3_s"].get<double>());
}

TEST_CASE("CFD-DEM check 4: upward seepage heaves a quartz column at the critical gradient",
          "[cfd_dem][verification]") {
  frostwall::test::TempDir dir;
  // 2 mm quartz grains in water, periodic sides, the Darcy velocity
  // ramping upward through the settled column.
  const json s = run_project(dir, "verify_fluidisation", [](json& p) {
    p["box"]["high"] = {0.012, 0.012, 0.04};
    p["grains"] = {{"diameter", 0.002},  {"density", 2650}, {"count", 320}, {"youngs_modulus", 1e7},
                   {"restitution", 0.5}, {"friction", 0.5}, {"seed", 3},    {"settle_time", 0.2}};
    p["fluid"] = {{"density", 1000}, {"viscosity", 1e-3}, {"cells", {1, 1, 20}}};
    p["flow"]["darcy_velocity"] = {{0, 0.01}, {0.6, 0.05}};
    p["time"] = {{"end", 0.6}, {"unit", "s"}, {"snapshots", {0.6}}};
  });
  const auto& f = s["minimum_fluidisation"];
  REQUIRE(f["velocity_m_s"].is_number());
  const double n = f["porosity"];
  const double critical = (2.65 - 1.0) * (1.0 - n);  // Terzaghi
  fmt::print("heave: porosity {:.4f}, gradient at heave {:.3f}, critical (G_s - 1)(1 - n) = {:.3f}\n", n,
             f["gradient"].get<double>(), critical);
  CHECK(f["critical_gradient"].get<double>() == Approx(critical).epsilon(1e-9));
  CHECK(f["gradient"].get<double>() == Approx(critical).epsilon(0.10));
}

TEST_CASE("CFD-DEM check 5: two MPI ranks give one rank's result", "[cfd_dem][mpi]") {
  auto shorter = [](json& p) {
    p["time"] = {{"end", 0.1}, {"unit", "s"}, {"snapshots", {0.1}}};
    p["grains"]["settle_time"] = 0.05;
    p["flow"]["darcy_velocity"] = {{0, 0.01}, {0.1, 0.03}};
  };
  const std::string two = "mpirun --allow-run-as-root --oversubscribe -np 2";
  SECTION("a fixed bed: to round-off") {
    frostwall::test::TempDir a, b;
    const json one = run_project(a, "verify_ergun", {}), pair = run_project(b, "verify_ergun", {}, two);
    CHECK(one["ranks"] == 1);
    CHECK(pair["ranks"] == 2);
    for (std::size_t k = 0; k < one["ergun"].size(); ++k) {
      CHECK(pair["ergun"][k]["pressure_drop_Pa"].get<double>() ==
            Approx(one["ergun"][k]["pressure_drop_Pa"].get<double>()).epsilon(1e-12));
      CHECK(pair["ergun"][k]["fluid_force_on_grains_N"].get<double>() ==
            Approx(one["ergun"][k]["fluid_force_on_grains_N"].get<double>()).epsilon(1e-10));
    }
  }
  SECTION("free grains falling through the water before they touch: to round-off") {
    auto falling = [](json& p) {
      p["time"] = {{"end", 0.002}, {"unit", "s"}, {"snapshots", {0.001, 0.002}}};
      p["grains"]["settle_time"] = 0.0;
    };
    frostwall::test::TempDir a, b;
    const json one = run_project(a, "verify_fluidisation", falling),
               pair = run_project(b, "verify_fluidisation", falling, two);
    CHECK(pair["ranks"] == 2);
    for (std::size_t k = 0; k < one["snapshots"].size(); ++k) {
      const auto &x = one["snapshots"][k], &y = pair["snapshots"][k];
      CHECK(y["bed_length_m"].get<double>() == Approx(x["bed_length_m"].get<double>()).epsilon(1e-12));
      CHECK(y["pressure_drop_Pa"].get<double>() == Approx(x["pressure_drop_Pa"].get<double>()).epsilon(1e-9));
      CHECK(y["mean_drag_N"][2].get<double>() == Approx(x["mean_drag_N"][2].get<double>()).epsilon(1e-9));
    }
  }
  SECTION("a bed settling and fluidising: the same bed within 1 %") {
    // Hundreds of collisions amplify round-off (the sum order of the
    // Allreduce differs): the grains' paths part, the bed does not.
    frostwall::test::TempDir a, b;
    const json one = run_project(a, "verify_fluidisation", shorter),
               pair = run_project(b, "verify_fluidisation", shorter, two);
    CHECK(pair["ranks"] == 2);
    const auto &x = one["snapshots"].back(), &y = pair["snapshots"].back();
    fmt::print("1 vs 2 ranks: bed {:.7f} / {:.7f} m, porosity {:.6f} / {:.6f}, dP {:.3f} / {:.3f} Pa\n",
               x["bed_length_m"].get<double>(), y["bed_length_m"].get<double>(), x["porosity"].get<double>(),
               y["porosity"].get<double>(), x["pressure_drop_Pa"].get<double>(), y["pressure_drop_Pa"].get<double>());
    CHECK(y["grains_in_soil"] == x["grains_in_soil"]);
    CHECK(y["bed_length_m"].get<double>() == Approx(x["bed_length_m"].get<double>()).epsilon(0.01));
    CHECK(y["porosity"].get<double>() == Approx(x["porosity"].get<double>()).epsilon(0.01));
    CHECK(y["pressure_drop_Pa"].get<double>() == Approx(x["pressure_drop_Pa"].get<double>()).epsilon(0.01));
  }
}

TEST_CASE("CFD-DEM: a settled packing is cached, and the next run starts from it", "[cfd_dem]") {
  // Both runs share one cache directory; the second settles nothing.
  frostwall::test::TempDir dir;
  auto brief = [](json& p) {
    p["time"] = {{"end", 0.02}, {"unit", "s"}, {"snapshots", {0.02}}};
    p["grains"]["settle_time"] = 0.05;
  };
  const json first = run_project(dir, "verify_fluidisation", brief);
  fs::rename(dir.path / "out", dir.path / "first");
  const json second = run_project(dir, "verify_fluidisation", brief);
  CHECK_FALSE(first["packing"]["read_from_cache"].get<bool>());
  CHECK(second["packing"]["read_from_cache"].get<bool>());
  CHECK(second["packing"]["cache"] == first["packing"]["cache"]);
  // The same grains (a restart file holds them in binary, with their
  // contacts' springs). The first forces are computed afresh from the
  // restart, so round-off parts the two paths and the dense bed's many
  // contacts amplify it: 0.02 s later the beds agree to 1e-3.
  CHECK(second["series_start"]["bed_length_m"].get<double>() ==
        Approx(first["series_start"]["bed_length_m"].get<double>()).epsilon(1e-12));
  CHECK(second["series_start"]["porosity"].get<double>() ==
        Approx(first["series_start"]["porosity"].get<double>()).epsilon(1e-12));
  CHECK(second["snapshots"][0]["bed_length_m"].get<double>() ==
        Approx(first["snapshots"][0]["bed_length_m"].get<double>()).epsilon(1e-3));
  // The neighbour lists' settings change the speed, not the answer: every
  // list is rebuilt once a grain moved half the skin, so a wider skin and
  // other bins find the same contacts. Over a few steps (the same cached
  // packing) the beds agree to round-off, which the grains' collisions
  // would amplify over a longer run (the sums' order differs).
  auto few_steps = [&](const json& neighbour) {
    return run_project(dir, "verify_fluidisation", [&](json& p) {
      brief(p);
      p["time"] = {{"end", 0.002}, {"unit", "s"}, {"snapshots", {0.002}}};
      if (!neighbour.is_null()) p["neighbour"] = neighbour;
    });
  };
  const json plain = few_steps(nullptr);
  const double d = read_json(projects / "verify_fluidisation.json")["grains"]["diameter"].get<double>();
  const json wide = few_steps({{"skin", 0.6 * d}, {"bin_size", 1.3 * d}});
  CHECK(wide["packing"]["read_from_cache"].get<bool>());
  CHECK(wide["dem_steps"] == plain["dem_steps"]);
  CHECK(wide["snapshots"][0]["bed_length_m"].get<double>() ==
        Approx(plain["snapshots"][0]["bed_length_m"].get<double>()).epsilon(1e-10));
  CHECK(wide["snapshots"][0]["porosity"].get<double>() ==
        Approx(plain["snapshots"][0]["porosity"].get<double>()).epsilon(1e-10));
  // Another seed is another packing: not the cached one.
  const json other = run_project(dir, "verify_fluidisation", [&](json& p) {
    brief(p);
    p["grains"]["seed"] = 8;
  });
  CHECK_FALSE(other["packing"]["read_from_cache"].get<bool>());
  // dem_commands.txt replays in LAMMPS's own program: the same 480 grains.
  const std::string replay = "cd '" + dir.path.string() +
                             "' && lmp -log none -in out/dem_commands.txt > replay.txt 2>&1";
  REQUIRE(std::system(replay.c_str()) == 0);
  std::ifstream in(dir.path / "replay.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  CHECK(text.find("480 atoms") != std::string::npos);
}

TEST_CASE("CFD-DEM: the report fills its section and the shared ones, and loads nothing", "[cfd_dem][report]") {
  frostwall::test::TempDir dir;
  run_project(dir, "verify_ergun", [](json& p) { p["output"]["report"] = true; });
  std::ifstream in(dir.path / "out" / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), {});
  CHECK(html.find("{{") == std::string::npos);
  CHECK(html.find("<section id=\"cfd_dem\">") != std::string::npos);
  CHECK(html.find("Temperature maps") == std::string::npos);  // no thermal section
  // One row per snapshot, the pressure drops as in summary.json.
  const json s = read_json(dir.path / "out" / "summary.json");
  for (const auto& sn : s["snapshots"])
    CHECK(html.find(fmt::format(">{:.2f}<", sn["pressure_drop_Pa"].get<double>())) != std::string::npos);
  CHECK(html.find("<svg") != std::string::npos);
  CHECK(html.find("http") == std::string::npos);
}

TEST_CASE("CFD-DEM: grains that fall into the cavity leave the soil (taken away), and every grain is counted",
          "[cfd_dem]") {
  // Grains placed above an unlined spherical cavity in still water fall:
  // those over it fall in.
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_fluidisation", [](json& p) {
    p["box"] = {{"low", {0, 0, 0}}, {"high", {0.02, 0.02, 0.02}}};
    p["cavity"] = {{"centre", {0.01, 0.01, 0.006}}, {"radius", 0.005}, {"drain", true}};
    p["grains"]["count"] = 400;
    p["grains"]["settle_time"] = 0.0;
    p["grains"]["fill"] = {{"low", {0, 0, 0.0115}}, {"high", {0.02, 0.02, 0.02}}};  // above the cavity
    p.erase("flow");
    p["fluid"]["cells"] = {4, 4, 4};
    p["time"] = {{"end", 0.08}, {"unit", "s"}, {"snapshots", {0.04, 0.08}}};
    p["output"]["vtk"] = true;
  });
  const auto& first = s["series_start"];
  CHECK(first["grains_in_soil"] == 400);
  const auto& last = s["snapshots"].back();
  const double fallen = s["soil"]["lost_to_cavity"], in_soil = last["grains_in_soil"];
  fmt::print("cavity: {} of 400 grains fell in by 0.08 s\n", fallen);
  CHECK(fallen > 0);
  CHECK(in_soil + fallen == 400);  // the leak takes them away: deleted, and counted
  CHECK(last["grains_in_cavity"] == 0);
  // The grain file flags exactly those.
  std::ifstream vtu(dir.path / "out" / "grains_0002.vtu");
  const std::string text((std::istreambuf_iterator<char>(vtu)), {});
  CHECK(text.find("Name=\"lost\"") != std::string::npos);
  CHECK(s["soil"]["cavity"]["mode"] == "drain");
  // Every grain carries its radius (ParaView scales spheres by it): half
  // its diameter; the file names its project and its time unit (s).
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir.path / "out" / "grains_0002.vtu").c_str());
  reader->Update();
  auto* grid = reader->GetOutput();
  vtkDataArray *radius = grid->GetPointData()->GetArray("radius"),
               *diameter = grid->GetPointData()->GetArray("diameter");
  REQUIRE(radius != nullptr);
  REQUIRE(grid->GetNumberOfPoints() > 0);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) CHECK(radius->GetTuple1(i) == 0.5 * diameter->GetTuple1(i));
  CHECK(grid->GetFieldData()->GetAbstractArray("project") != nullptr);
  CHECK(grid->GetFieldData()->GetAbstractArray("time_unit")->GetVariantValue(0).ToString() == "s");
  CHECK(fs::exists(dir.path / "out" / "open_in_paraview.py"));
}

TEST_CASE("CFD-DEM: a kept cavity holds the grains that fall in, and every grain is counted", "[cfd_dem]") {
  // The same fall with the cavity's default: what falls in stays.
  frostwall::test::TempDir dir;
  const json s = run_project(dir, "verify_fluidisation", [](json& p) {
    p["box"] = {{"low", {0, 0, 0}}, {"high", {0.02, 0.02, 0.02}}};
    p["cavity"] = {{"centre", {0.01, 0.01, 0.006}}, {"radius", 0.005}};
    p["grains"]["count"] = 400;
    p["grains"]["settle_time"] = 0.0;
    p["grains"]["fill"] = {{"low", {0, 0, 0.0115}}, {"high", {0.02, 0.02, 0.02}}};
    p.erase("flow");
    p["fluid"]["cells"] = {4, 4, 4};
    p["time"] = {{"end", 0.08}, {"unit", "s"}, {"snapshots", {0.04, 0.08}}};
  });
  const auto& soil = s["soil"];
  CHECK(soil["cavity"]["mode"] == "keep");
  for (const auto& row : soil["series"]) {
    CHECK(row["grains_in_model"] == 400);  // nothing is deleted
    CHECK(row["grains_in_soil"].get<double>() + row["lost_to_cavity"].get<double>() == 400);
    CHECK(row["grains_in_cavity"].get<double>() <= row["lost_to_cavity"].get<double>());
  }
  const auto& end = soil["series"].back();
  fmt::print("kept cavity: {} of 400 grains fell in by 0.08 s, {} in it\n", end["lost_to_cavity"].get<double>(),
             end["grains_in_cavity"].get<double>());
  CHECK(end["lost_to_cavity"].get<double>() > 0);
  CHECK(end["grains_in_cavity"].get<double>() > 0);  // they stay
  CHECK(s["grains"] == 400);
}
