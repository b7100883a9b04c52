// The fluid's forces on one grain, one small type each, chosen by name in
// the project ("forces": ["difelice_drag", "pressure_gradient",
// "buoyancy"]), as CFDEMcoupling's force models are. The grid's pressure
// is the excess over hydrostatic, so -V grad p does not contain the
// buoyancy: "buoyancy" adds Archimedes' force once, and only it.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pore_water/drag_law.hpp"
#include "pore_water/fluid_grid.hpp"

namespace frostwall::pore_water {

enum class ForceKind { drag, pressure_gradient, buoyancy };

// A drag written as K (u - v): the coefficient K (N s/m) and the fluid
// velocity u it pulls the grain towards. Held with the grain's velocity of
// each DEM step, it is the semi-implicit momentum exchange.
struct LinearDrag {
  double coefficient = 0.0;
  Vec3 velocity = Vec3::Zero();
};

class FluidForce {
 public:
  virtual ~FluidForce() = default;
  virtual ForceKind kind() const = 0;
  // The force (N) on a grain of diameter d moving at v, where the fluid
  // is as sampled; gravity in m/s2.
  virtual Vec3 force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3& v, const FluidSample& s) const = 0;
  // A drag's K and u at this slip (force() = K (u - v)); none for the other kinds.
  virtual std::optional<LinearDrag> linear_drag(const Fluid&, double, const Vec3&, const FluidSample&) const {
    return std::nullopt;
  }
};

// Drag from a drag law on the interstitial slip u_f - v at the local porosity.
class DragForce final : public FluidForce {
 public:
  explicit DragForce(std::unique_ptr<DragLaw> law) : law_(std::move(law)) {}
  ForceKind kind() const override { return ForceKind::drag; }
  Vec3 force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3& v, const FluidSample& s) const override;
  std::optional<LinearDrag> linear_drag(const Fluid& fluid, double d, const Vec3& v,
                                        const FluidSample& s) const override;

 private:
  std::unique_ptr<DragLaw> law_;
};

// Gidaspow (1994): the drag the fluid grid's own resistance implies
// (Ergun below porosity 0.8, Wen-Yu above, blended; bed_resistance.hpp),
// V_p K (u - v) from FluidSample::drag_coefficient and drag_velocity, so
// that a cell's grains take exactly the momentum its water loses (drag
// plus -V grad p over a bed = the pressure drop times its area).
class GridDragForce final : public FluidForce {
 public:
  ForceKind kind() const override { return ForceKind::drag; }
  Vec3 force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3& v, const FluidSample& s) const override;
  std::optional<LinearDrag> linear_drag(const Fluid& fluid, double d, const Vec3& v,
                                        const FluidSample& s) const override;
};

// -V_p grad p (excess pressure).
class PressureGradientForce final : public FluidForce {
 public:
  ForceKind kind() const override { return ForceKind::pressure_gradient; }
  Vec3 force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3& v, const FluidSample& s) const override;
};

// -rho_f V_p g: the hydrostatic pressure's push.
class BuoyancyForce final : public FluidForce {
 public:
  ForceKind kind() const override { return ForceKind::buoyancy; }
  Vec3 force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3& v, const FluidSample& s) const override;
};

// By name: difelice_drag, gidaspow_drag, schiller_naumann_drag, pressure_gradient,
// buoyancy (the names lib/project accepts). Throws std::invalid_argument
// for any other.
std::unique_ptr<FluidForce> make_fluid_force(const std::string& name);
std::vector<std::unique_ptr<FluidForce>> make_fluid_forces(const std::vector<std::string>& names);

}  // namespace frostwall::pore_water
