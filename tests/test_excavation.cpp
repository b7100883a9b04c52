// Sinking the shaft: the excavation inside the frozen wall.
// References:
//  - energy: the model's heat changes by what its boundaries (pipes, far
//    field, the face) brought in, less the heat of the ground taken out,
//    plus the lining as placed and its heat of hydration, within 1e-6; and
//    the heat taken out is that of the same ground, found in a run without
//    the excavation stopped on the day (to 1e-9);
//  - a film of 1e9 W/(m2 K) holds the face at the air: the face's
//    temperature within 0.1 K of it, and the field within 0.1 K of the
//    field at 1e12;
//  - steady state: a ring of pipes of radius a at spacing 2 pi a acts as
//    one circle at the pipes' temperature (the row's logarithmic term
//    ln(s / 2 pi a) vanishes); with the face held warm inside it the inner
//    frozen boundary r_i in steady state satisfies
//      k_u (T_face - T_f) / ln(r_i / a_face) = k_f (T_f - T_pipe) / ln(R / r_i),
//    within 2 % on OA (through a pipe) and OB (between two);
//  - hydration: a lining that exchanges nothing (insulating material, no
//    film) warms by the heat released over its heat capacity, within 1 %;
//  - the wall thins from the inside: warm air moves the inner frozen
//    boundary out and the wall is thinner than without the excavation;
//    with the excavation after the run's end the closure day and the wall
//    are the run's without it, to 1e-9.
#include <catch2/catch.hpp>

#include <cmath>
#include <nlohmann/json.hpp>

#include "freezing/excavation_face.hpp"
#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"
#include "project/units.hpp"
#include "shipped_run.hpp"
#include "temp_dir.hpp"

using namespace frostwall;
using nlohmann::json;

namespace {

constexpr double day = project::seconds_per_day;

// The single ring in sand, 5 cm, 60 days, dug on day 30 (a wall check at
// 1 MPa, Domke), with the excavation block patched by `excavation`.
project::Project ring(const std::filesystem::path& out, const json& excavation) {
  json patch = {{"numerics", {{"spacing", 0.05}, {"error_estimate", false}}},
                {"time", {{"end", 60}, {"unit", "d"}, {"snapshots", {30, 60}}}},
                {"design", {{"strength", {{"a", 2.0}, {"b", 1.5}}}, {"pressure", {{"value_MPa", 1.0}}}}},
                {"output", {{"vtk", false}, {"report", false}}}};
  if (!excavation.is_null()) {
    patch["excavation"] = {
        {"start_day", 30}, {"rate_m_per_day", 1.0}, {"air_temperature", 10.0}, {"heat_transfer", 10.0}};
    patch["excavation"].merge_patch(excavation);
  }
  return test::shipped_project("single_ring_sand.json", patch, out);
}

// A ring of 30 pipes of 10 cm on 1.5 m (spacing 2 pi a), sand at 20 C,
// the face at 0.75 m dug on day 0 behind a film h from air at 20 C.
project::Project dense_ring(const std::filesystem::path& out, double h, double spacing, double end_day,
                            const json& lining = nullptr) {
  json j = {
      {"name", "dense ring"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 1.5}, {"count", 30}}}}},
      {"shaft", {{"excavation_radius", 0.75}}},
      {"pipe", {{"diameter", 0.1}, {"temperature", -20.0}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 3.0}, {"initial_temperature", 20.0}, {"far_field", {{"temperature", 20.0}}}}},
      {"time", {{"end", end_day}, {"unit", "d"}, {"snapshots", {end_day / 2, end_day}}}},
      {"numerics", {{"spacing", spacing}, {"error_estimate", false}}},
      {"excavation", {{"start_day", 0}, {"rate_m_per_day", 1.0}, {"air_temperature", 20.0}, {"heat_transfer", h}}},
      {"output", {{"directory", out.string()}, {"vtk", false}, {"report", false}}}};
  if (!lining.is_null()) j["excavation"]["lining"] = lining;
  return project::parse_project(j.dump());
}

json run_json(const project::Project& p) {
  freezing::Model m = freezing::build_model(p);
  return summary::to_json(freezing::run_heat(p, m, {}));
}

}  // namespace

TEST_CASE("Excavation: the heat taken out, through the face and of the lining closes the model's balance",
          "[excavation]") {
  test::TempDir dir("excavation_energy"), before("excavation_before");
  const json lining = {{"thickness", 0.4},
                       {"conductivity", 1.8},
                       {"heat_capacity", 900},
                       {"density", 2400},
                       {"placed_after_days", 3},
                       {"placement_temperature", 12.0},
                       {"hydration_heat", {{"total", 60000}, {"release_days", 1.0}}}};
  const json s = run_json(ring(dir.path, {{"lining", lining}}));
  const json& heat = s["heat_balance"]["from_boundaries"];
  double total = 0.0, largest = 0.0;
  for (const auto& [name, q] : heat.items())
    total += q.get<double>(), largest = std::max(largest, std::abs(q.get<double>()));
  const double stored = s["heat_balance"]["stored_change"];
  INFO("stored " << stored << " from every source " << total);
  CHECK(std::abs(total - stored) <= 1e-6 * std::abs(stored));
  CHECK(heat["face"].get<double>() != 0.0);
  CHECK(heat["hydration"].get<double>() > 0.0);

  // The same ground, stopped on day 30 without the excavation: its heat
  // inside the radius is what the excavation took out.
  const project::Project p = ring(before.path, nullptr);
  freezing::Model m = freezing::build_model(p);
  freezing::SteppedHeatRun run(p, m, {});
  run.advance_to(30.0 * day);
  double inside = 0.0;
  for (std::size_t i = 0; i < m.model->free_count(); ++i)
    if (m.particles().position[i].norm() < 3.5) inside += m.model->volume()[i] * m.model->enthalpy()[i];
  CHECK(-heat["excavated"].get<double>() == Approx(inside).epsilon(1e-9));
  // The lining's heat of hydration: its volume (the particles' share of
  // the annulus in the wedge) times density times the heat released.
  const double wedge = s["wedge"]["angle_deg"].get<double>() / 360.0;
  const double volume = M_PI * (3.5 * 3.5 - 3.1 * 3.1) * wedge;
  CHECK(heat["hydration"].get<double>() == Approx(volume * 2400 * 60000 * -std::expm1(-27.0)).epsilon(0.05));
}

TEST_CASE("Excavation: a very large film holds the face at the air", "[excavation]") {
  test::TempDir a("excavation_film_a"), b("excavation_film_b");
  auto face_state = [](const project::Project& p) {
    freezing::Model m = freezing::build_model(p);
    freezing::SteppedHeatRun run(p, m, {});
    run.advance_to(20.0 * day);
    const double wall = m.model->wall_temperatures(std::size_t(freezing::face_boundary(*m.scene)))[0];
    std::vector<double> T(m.model->temperature().begin(), m.model->temperature().begin() + m.model->free_count());
    for (std::size_t i = 0; i < T.size(); ++i)
      if (m.model->removed(i)) T[i] = 0.0;
    return std::make_pair(wall, T);
  };
  const auto [wall, field] = face_state(dense_ring(a.path, 1e9, 0.03, 20));
  const auto [wall_held, field_held] = face_state(dense_ring(b.path, 1e12, 0.03, 20));
  CHECK(std::abs(wall - 20.0) < 0.1);
  double worst = 0.0;
  for (std::size_t i = 0; i < field.size(); ++i) worst = std::max(worst, std::abs(field[i] - field_held[i]));
  INFO("face " << wall << " C; largest difference from the face held " << worst << " K");
  CHECK(worst < 0.1);
}

TEST_CASE("Excavation: the steady inner frozen boundary inside a dense ring is the radial solution's", "[excavation]") {
  test::TempDir dir("excavation_steady");
  const json s = run_json(dense_ring(dir.path, 1e9, 0.02, 100));
  const auto sand = *project::builtin_soil("sand");
  const double ku = sand.unfrozen.conductivity[0], kf = sand.frozen.conductivity[0];
  const double beta = ku * (20.0 - 0.0) / (kf * (0.0 - -20.0));
  const double exact = std::exp((std::log(0.75) + beta * std::log(1.5)) / (1.0 + beta));
  const json& half = s["wall"][0];
  const json& end = s["wall"][1];
  for (const char* ray : {"OA", "OB"}) {
    const double r = end[ray]["inner"];
    INFO(ray << ": inner boundary " << r << " m against " << exact << " m");
    CHECK(r == Approx(exact).epsilon(0.02));
    CHECK(r == Approx(half[ray]["inner"].get<double>()).epsilon(1e-3));  // steady by day 50
  }
}

TEST_CASE("Excavation: an insulated lining warms by its heat of hydration over its heat capacity", "[excavation]") {
  test::TempDir dir("excavation_hydration");
  // A released curve (J/kg by day after placing).
  const json lining = {{"thickness", 0.2},
                       {"conductivity", 1e-6},
                       {"heat_capacity", 900},
                       {"density", 2400},
                       {"placed_after_days", 1},
                       {"placement_temperature", 10.0},
                       {"hydration_heat", {{0.5, 20000}, {1, 35000}, {3, 55000}, {7, 60000}}}};
  project::Project p = dense_ring(dir.path, 1e9, 0.03, 10, lining);
  p.excavation->heat_transfer = 0.0;  // no film: the lining exchanges nothing
  freezing::Model m = freezing::build_model(p);
  freezing::SteppedHeatRun run(p, m, {});
  run.advance_to(10.0 * day);
  double heat = 0.0, volume = 0.0;
  for (std::size_t i = 0; i < m.model->free_count(); ++i) {
    const double r = m.particles().position[i].norm();
    if (r < 0.55 || r >= 0.75) continue;
    volume += m.model->volume()[i];
    heat += m.model->volume()[i] * m.model->temperature()[i];
  }
  const double rise = heat / volume - 10.0, adiabatic = 60000.0 / 900.0;
  INFO("mean rise " << rise << " K against " << adiabatic << " K");
  CHECK(rise == Approx(adiabatic).epsilon(0.01));
}

TEST_CASE("Excavation: warm air thins the wall from the inside, and dug after the run's end nothing changes",
          "[excavation]") {
  test::TempDir dug("excavation_dug"), kept("excavation_kept"), late("excavation_late");
  const json warm = {{"air_temperature", 20.0}, {"heat_transfer", 20.0}};
  const json s = run_json(ring(dug.path, warm));
  const json base = run_json(ring(kept.path, nullptr));
  const json after_end = run_json(ring(late.path, {{"start_day", 100}}));
  // At the end the inner frozen boundary lies further out, the wall thinner.
  const json& w = s["wall"].back();
  const json& w0 = base["wall"].back();
  INFO("inner " << w["OB"]["inner"] << " / " << w0["OB"]["inner"] << " m, thinnest " << w["min_thickness"] << " / "
                << w0["min_thickness"] << " m");
  CHECK(w["OB"]["inner"].get<double>() > w0["OB"]["inner"].get<double>() + 0.05);
  CHECK(w["min_thickness"].get<double>() < w0["min_thickness"].get<double>() - 0.05);
  // The margin after the day is below the margin the wall had without it.
  const json& e = s["excavation"];
  REQUIRE(e["margin_min"].is_number());
  CHECK(e["day"].get<double>() == 30.0);
  const double margin_kept = w0["min_thickness"].get<double>() - w0["required_thickness"].get<double>();
  CHECK(e["series"].back()["margin"].get<double>() < margin_kept - 0.05);
  // Dug after the end: the closure day and every wall reading as without
  // (to round-off: the face's idle pairs sum the rows in another order).
  CHECK(after_end["closure_time_days"].get<double>() == Approx(base["closure_time_days"].get<double>()).epsilon(1e-9));
  for (std::size_t k = 0; k < base["wall"].size(); ++k)
    CHECK(after_end["wall"][k]["min_thickness"].get<double>() ==
          Approx(base["wall"][k]["min_thickness"].get<double>()).epsilon(1e-9));
  CHECK(after_end["excavation"]["thinnest_after"].is_null());
}
