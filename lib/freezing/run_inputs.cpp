// The checks a heat run makes on its project before any work: what the
// loader cannot judge alone (the soil's phase law with the water's).
#include <fmt/format.h>
#include <optional>
#include <utility>

#include "freezing/heat_run.hpp"
#include "freezing/model.hpp"
#include "groundwater/permeability_law.hpp"
#include "io/output_directory.hpp"
#include "project/units.hpp"
#include "thermal/phase_change.hpp"

namespace frostwall::freezing {

using project::Project;

namespace {

// Water enters at the far field's temperature and flows through the
// ground as it starts: where the permeability law holds either at its
// floor, the ice blocks all flow and the run would be still water with a
// regional flux that cannot pass.
void check_water_can_flow(const Project& p) {
  const thermal::PhaseChangeLaw soil(p.soil);
  const auto law = groundwater::permeability_law(p.groundwater->law);
  const std::pair<const char*, std::optional<double>> states[] = {
      {"domain.initial_temperature", std::optional<double>(p.domain.initial_temperature)},
      {"domain.far_field.temperature", p.domain.far_field_temperature}};
  for (const auto& [where, T] : states) {
    if (!T) continue;
    const double f = soil.liquid_fraction(soil.enthalpy(*T));
    if (law.relative(f) <= law.floor * (1.0 + 1e-9))
      throw project::ProjectError({fmt::format(
          "groundwater.permeability_law: blocks all flow at {} = {:g} C (liquid fraction {:.3g}, the law at its "
          "floor {:g}): start the ground above its freezing range, or drop the groundwater block",
          where, *T, f, law.floor)});
  }
}

// The explicit schemes carry the water's heat in sub-steps held to the
// advective Courant limit, about h C_min / (2 rho_w c_w q) for the limited
// faces (the finest spacing h; on the scaled ring at 1 m/d the run's 592
// steps were 1.5 times this count). Past a hundred thousand of them a
// run does not end in a working day; the coupled step follows any flux.
void check_explicit_advection(const Project& p) {
  const auto& g = *p.groundwater;
  if (g.advection == project::Advection::coupled || g.advection == project::Advection::implicit || g.speed() == 0.0)
    return;
  const thermal::PhaseChangeLaw soil(p.soil);
  const double courant = resolved_spacing(p) * soil.smallest_heat_capacity() /
                         (g.water_density * g.water_heat_capacity * g.speed());
  const double step = g.advection == project::Advection::limited ? 0.5 * courant : courant;
  constexpr double most_steps = 1e5;
  if (const double steps = p.time.end / step; steps > most_steps)
    throw project::ProjectError({fmt::format(
        "groundwater.darcy_flux: {:g} m/d needs about {:.2g} explicit advection steps of {:.3g} s with "
        "\"advection\": \"{}\" (more than {:g}); the coupled step follows any flux (\"advection\": \"coupled\" "
        "with the implicit integrator, the default)",
        g.speed() * project::seconds_per_day, steps, step,
        g.advection == project::Advection::limited ? "limited" : "upwind", most_steps)});
}

}  // namespace

void check_run_inputs(const Project& p) {
  // The regional flow is held on the far field: an adiabatic one has none.
  if (p.groundwater && std::holds_alternative<project::ShaftSection>(p.geometry) && !p.domain.far_field_temperature)
    throw project::ProjectError(
        {"groundwater: needs domain.far_field_temperature (the far field holds the regional flow "
         "and the temperature of the water that enters)"});
  if (p.groundwater) {
    check_water_can_flow(p);
    check_explicit_advection(p);
  }
  io::check_output_directory(p.output.directory);
}

}  // namespace frostwall::freezing
