// The wall check through the command line (freezing/design_check.hpp): a
// scaled ring with the frozen soil's strength and the ground pressure.
// Every snapshot's allowable strength, the Domke thickness and the
// utilisation are recomputed here by hand from the summary's own mean
// temperature and thinnest wall; the design is met on the first snapshot
// with utilisation at or below 1; a stronger soil needs less.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/core.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include "cli.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json ring_with_design(double strength_slope) {
  return {
      {"name", "scaled ring with a wall check"},
      {"layout", {{"pattern", "single"}, {"outer_ring", {{"radius", 0.8}, {"count", 6}, {"start_angle_deg", 0.0}}}}},
      {"shaft", {{"excavation_radius", 0.5}}},
      {"pipe", {{"diameter", 0.127}, {"temperature", -20.0}}},
      {"soil", "sand"},
      {"domain", {{"outer_radius", 2.5}, {"initial_temperature", 10.0}, {"far_field", {{"temperature", 10.0}}}}},
      {"time", {{"end", 12}, {"unit", "d"}, {"snapshots", {4, 6, 8, 10, 12}}}},
      {"numerics", {{"placement", "lattice"}, {"spacing", 0.05}}},
      {"design",
       {{"strength", {{"a", 1.0}, {"b", strength_slope}}},  // illustrative: sigma_c = 1 + b |T| MPa
        {"depth", 80.0},
        {"pressure", {{"gradient_MPa_per_m", 0.013}}},
        {"friction_angle", 10.0}}},
      {"output", {{"directory", "out"}, {"vtk", false}, {"report", false}}}};
}

json run(const json& project) { return frostwall::test::run_project(project); }

}  // namespace

TEST_CASE("The wall check: required thickness from pressure and strength, utilisation, the day it is met",
          "[freezing][design][cli]") {
  const json weak = run(ring_with_design(0.3)), strong = run(ring_with_design(0.6));
  const double a = 0.5, P = 0.013 * 80.0;
  CHECK(weak["design"]["pressure_MPa"].get<double>() == Approx(P).epsilon(1e-12));
  CHECK(weak["design"]["formula"] == "domke");
  std::optional<double> first_met;
  double last_unmet = 0.0;  // the last snapshot before first_met with utilisation above 1
  bool stays = false;
  for (const auto& w : weak["wall"]) {
    INFO("day " << w["day"].get<double>());
    REQUIRE(w["required_by"].size() == 5);
    if (w["mean_temperature_thinnest"].is_null()) {
      CHECK(w["utilisation"].is_null());
      stays = false;
      continue;
    }
    const double T = w["mean_temperature_thinnest"].get<double>();
    CHECK(T < 0.0);
    const double s = 0.5 * (1.0 + 0.3 * std::abs(T));  // allowable factor 0.5 by default
    CHECK(w["allowable_strength"].get<double>() == Approx(s).epsilon(1e-12));
    const double domke = a * (0.29 * P / s + 2.3 * (P / s) * (P / s));
    CHECK(w["required_thickness"].get<double>() == Approx(domke).epsilon(1e-12));
    CHECK(w["required_by"]["plastic_tresca"].get<double>() == Approx(a * std::expm1(P / s)).epsilon(1e-12));
    // Mohr-Coulomb with a little friction asks less than Tresca's plastic limit.
    CHECK(w["required_by"]["plastic_mohr_coulomb"].get<double>() < w["required_by"]["plastic_tresca"].get<double>());
    const double thinnest = w["min_thickness"].get<double>();
    if (thinnest > 0.0) {
      const double u = w["utilisation"].get<double>();
      CHECK(u == Approx(domke / thinnest).epsilon(1e-12));
      if (u <= 1.0 && !first_met) first_met = w["day"].get<double>(), stays = true;
      if (u > 1.0) stays = false;
      if (u > 1.0 && !first_met) last_unmet = w["day"].get<double>();
    }
  }
  WARN(fmt::format("met on day {} (weak soil), day {} (strong soil); the weak wall's last utilisation {:.3f}",
                   weak["design"]["met_day"].dump(), strong["design"]["met_day"].dump(),
                   weak["wall"].back()["utilisation"].get<double>()));
  REQUIRE(first_met.has_value());
  // The met day comes from every output interval, so it lies between the
  // last snapshot that fails and the first that passes.
  CHECK(weak["design"]["met_day"].get<double>() <= *first_met);
  CHECK(weak["design"]["met_day"].get<double>() > last_unmet);
  if (!stays) CHECK_FALSE(weak["design"]["stays_met"].get<bool>());
  CHECK(weak["design"]["pass"].get<bool>());
  // A stronger soil at the same temperatures needs less, and is met no later.
  const auto& w_last = weak["wall"].back();
  const auto& s_last = strong["wall"].back();
  CHECK(s_last["required_thickness"].get<double>() < w_last["required_thickness"].get<double>());
  REQUIRE(strong["design"]["met_day"].is_number());
  CHECK(strong["design"]["met_day"].get<double>() <= weak["design"]["met_day"].get<double>());
}

TEST_CASE(
    "The wall on a design isotherm: thinner than the frozen wall, the same at the front's temperature, and the check uses it",
    "[freezing][design][cli]") {
  // The sand, freezing over 2 K below 0 degC: the liquid fraction is then
  // linear in temperature through the band of freezing particles, 0.5 at
  // -1 degC (with no range, T = 0 across the whole band and the 0 degC wall
  // takes in all of it, tens of centimetres wider than the 0.5 front).
  const json sand_with_range = {{"name", "sand freezing over 2 K"},
                                {"density", 2090},
                                {"unfrozen", {{"conductivity", 1.86}, {"heat_capacity", 1465.1}}},
                                {"frozen", {{"conductivity", 2.56}, {"heat_capacity", 1088.4}}},
                                {"latent_heat", 52875.8},
                                {"freezing_point", 0.0},
                                {"freezing_range", 2.0}};
  auto with_isotherm = [&](std::optional<double> isotherm) {
    json p = ring_with_design(0.3);
    p["soil"] = sand_with_range;
    if (isotherm) p["design"]["isotherm"] = *isotherm;
    return run(p);
  };
  const json cold = with_isotherm(-8.0), colder = with_isotherm(-12.0), front = with_isotherm(-1.0);
  CHECK(cold["design"]["isotherm"].get<double>() == -8.0);
  const double spacing = 0.05, a = 0.5, P = 0.013 * 80.0;
  int compared = 0;
  for (std::size_t k = 0; k < cold["wall"].size(); ++k) {
    const auto &w = cold["wall"][k], &w12 = colder["wall"][k], &w0 = front["wall"][k];
    INFO("day " << w["day"].get<double>());
    const double frozen = w["min_thickness"].get<double>(), iso = w["isotherm_thickness"].get<double>();
    // The same run but for the isotherm: the frozen wall is the same.
    CHECK(w0["min_thickness"].get<double>() == frozen);
    if (frozen == 0.0) {
      CHECK(iso == 0.0);
      continue;
    }
    ++compared;
    CHECK(iso < frozen);
    CHECK(w12["isotherm_thickness"].get<double>() <= iso);
    // On the front's own temperature the two walls are one (to the
    // sampling: fields interpolated from particles on both sides of the band).
    CHECK(std::abs(w0["isotherm_thickness"].get<double>() - frozen) <= 0.25 * spacing);
    if (iso > 0.0) {
      const double T = w["isotherm_mean_temperature"].get<double>();
      CHECK(T <= -8.0);
      CHECK(T < w["mean_temperature_thinnest"].get<double>());
      // The check is on the isotherm wall: strength at its mean temperature.
      const double s = 0.5 * (1.0 + 0.3 * std::abs(T));
      const double domke = a * (0.29 * P / s + 2.3 * (P / s) * (P / s));
      CHECK(w["required_thickness"].get<double>() == Approx(domke).epsilon(1e-12));
      CHECK(w["utilisation"].get<double>() == Approx(domke / iso).epsilon(1e-12));
    }
  }
  CHECK(compared >= 3);
  WARN(fmt::format(
      "last day: frozen wall {:.3f} m, -8 degC wall {:.3f} m, -12 degC wall {:.3f} m, -1 degC wall {:.3f} m",
      cold["wall"].back()["min_thickness"].get<double>(), cold["wall"].back()["isotherm_thickness"].get<double>(),
      colder["wall"].back()["isotherm_thickness"].get<double>(),
      front["wall"].back()["isotherm_thickness"].get<double>()));
  // Measured on a colder wall the design is met no earlier.
  REQUIRE(cold["design"]["met_day"].is_number());
  const json plain = with_isotherm(std::nullopt);
  REQUIRE(plain["design"]["met_day"].is_number());
  CHECK(cold["design"]["met_day"].get<double>() >= plain["design"]["met_day"].get<double>());
}
