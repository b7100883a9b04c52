// The "mechanics" block (README, project-file fields beyond the spec).
#include <cmath>
#include <fmt/format.h>

#include "project/json_reader.hpp"
#include "project/mechanics.hpp"

namespace frostwall::project {

namespace {

Support read_support(const detail::Node& n) {
  Support s;
  if (!n.present()) return s;  // free
  if (n.json().is_string()) {
    s.kind = n.choice<Support::Kind>(
                  "support",
                  {{"free", Support::Kind::free}, {"roller", Support::Kind::roller}, {"fixed", Support::Kind::fixed}})
                 .value_or(Support::Kind::free);
    return s;
  }
  if (!n.object({"displacement"})) return s;
  const detail::Node d = n["displacement"].required();
  if (!d.present()) return s;
  if (!d.json().is_array() || d.json().size() != 2 || !d.json()[0].is_number() || !d.json()[1].is_number()) {
    d.problem("must be [ux, uy] in metres, got " + d.shown());
    return s;
  }
  s.kind = Support::Kind::displacement;
  s.ux = d.json()[0].get<double>();
  s.uy = d.json()[1].get<double>();
  return s;
}

}  // namespace

Mechanics read_mechanics(const detail::Node& n, std::vector<std::string>& warnings) {
  Mechanics m;
  if (!n.object({"material", "plane", "supports", "relaxation", "kinematics", "equilibrium", "cracks_insulate",
                 "freezing_expansion"}))
    return m;
  m.cracks_insulate = n["cracks_insulate"].boolean().value_or(false);
  m.linear_kinematics =
      n["kinematics"].choice<bool>("kinematics", {{"linear", true}, {"nonlinear", false}}).value_or(true);
  using Equilibrium = Mechanics::Equilibrium;
  const auto equilibrium = n["equilibrium"].choice<Equilibrium>(
      "equilibrium method", {{"direct", Equilibrium::direct}, {"dynamic_relaxation", Equilibrium::dynamic_relaxation}});
  m.equilibrium = equilibrium.value_or(m.linear_kinematics ? Equilibrium::direct : Equilibrium::dynamic_relaxation);
  if (equilibrium == Equilibrium::direct && !m.linear_kinematics)
    n["equilibrium"].problem("\"direct\" needs \"kinematics\": \"linear\" (nonlinear kinematics relax dynamically)");
  const detail::Node mat = n["material"].required();
  m.plane = n["plane"].choice<Plane>("plane", {{"strain", Plane::strain}, {"stress", Plane::stress}}).value_or(m.plane);
  if (mat.object(
          {"elastic_modulus", "poisson_ratio", "thermal_expansion", "fracture_energy", "reference_temperature"})) {
    m.material.elastic_modulus = mat["elastic_modulus"].required().positive().value_or(0.0);
    m.material.thermal_expansion = mat["thermal_expansion"].required().number().value_or(0.0);
    m.material.fracture_energy = mat["fracture_energy"].positive();
    m.material.reference_temperature = mat["reference_temperature"].required().number().value_or(0.0);
    const double fixed_nu = m.plane == Plane::strain ? 0.25 : 1.0 / 3.0;
    if (const auto nu = mat["poisson_ratio"].number()) {
      if (*nu <= -1.0 || *nu >= 0.5) mat["poisson_ratio"].problem(fmt::format("must be in (-1, 0.5), got {}", *nu));
      m.material.poisson_ratio = *nu;
      if (std::abs(*nu - fixed_nu) > 1e-9)
        warnings.push_back(fmt::format(
            "mechanics.material.poisson_ratio: bond-based peridynamics fixes Poisson's ratio at {} in plane {}; "
            "the run uses {}, not {}",
            m.plane == Plane::strain ? "1/4" : "1/3", m.plane == Plane::strain ? "strain" : "stress",
            m.plane == Plane::strain ? "1/4" : "1/3", *nu));
    }
    m.material.poisson_ratio = fixed_nu;
  }
  if (const detail::Node s = n["supports"]; s.object({"left", "right", "bottom", "top"})) {
    m.left = read_support(s["left"]);
    m.right = read_support(s["right"]);
    m.bottom = read_support(s["bottom"]);
    m.top = read_support(s["top"]);
  }
  if (const detail::Node r = n["relaxation"];
      r.object({"tolerance", "temperature_change", "max_iterations", "frozen_fraction_change"})) {
    m.tolerance = r["tolerance"].positive().value_or(m.tolerance);
    m.temperature_change = r["temperature_change"].positive();
    m.max_iterations = r["max_iterations"].count().value_or(m.max_iterations);
    if (const auto f = r["frozen_fraction_change"].positive()) {
      if (*f > 1.0) r["frozen_fraction_change"].problem(fmt::format("must be at most 1, got {}", *f));
      else m.frozen_fraction_change = *f;
    }
  }
  // Only with pores (load_pores.cpp checks that, and sets the default).
  if (const detail::Node f = n["freezing_expansion"]; f.object({"model", "volume_change", "ice_elastic_modulus"})) {
    using Model = FreezingExpansion::Model;
    FreezingExpansion e;
    e.model = f["model"]
                  .required()
                  .choice<Model>("freezing expansion model", {{"rim_displacement", Model::rim_displacement},
                                                              {"ice_eigenstrain", Model::ice_eigenstrain}})
                  .value_or(e.model);
    e.volume_change = f["volume_change"].non_negative().value_or(e.volume_change);
    e.ice_elastic_modulus = f["ice_elastic_modulus"].positive().value_or(e.ice_elastic_modulus);
    m.freezing_expansion = e;
  }
  return m;
}

}  // namespace frostwall::project
