#include "pore_water/grain_forces.hpp"

#include <stdexcept>

#include "particles/sphere.hpp"

namespace frostwall::pore_water {

using particles::sphere_volume_of_diameter;

Vec3 DragForce::force(const Fluid& fluid, const Vec3&, double d, const Vec3& v, const FluidSample& s) const {
  return law_->force(fluid, d, s.porosity, s.fluid_velocity - v);
}

std::optional<LinearDrag> DragForce::linear_drag(const Fluid& fluid, double d, const Vec3& v,
                                                 const FluidSample& s) const {
  // The laws' force lies along the slip: K = |F| / |slip|, at a vanishing
  // slip the limit of the law's creeping-flow branch.
  constexpr double tiny = 1e-9;  // m/s
  const Vec3 slip = s.fluid_velocity - v;
  const double w = slip.norm();
  const Vec3 probe = w > tiny ? slip : Vec3(tiny, 0.0, 0.0);
  return LinearDrag{law_->force(fluid, d, s.porosity, probe).norm() / probe.norm(), s.fluid_velocity};
}

std::optional<LinearDrag> GridDragForce::linear_drag(const Fluid&, double d, const Vec3&, const FluidSample& s) const {
  return LinearDrag{sphere_volume_of_diameter(d) * s.drag_coefficient, s.drag_velocity};
}

Vec3 GridDragForce::force(const Fluid&, const Vec3&, double d, const Vec3& v, const FluidSample& s) const {
  return sphere_volume_of_diameter(d) * s.drag_coefficient * (s.drag_velocity - v);
}

Vec3 PressureGradientForce::force(const Fluid&, const Vec3&, double d, const Vec3&, const FluidSample& s) const {
  return -sphere_volume_of_diameter(d) * s.pressure_gradient;
}

Vec3 BuoyancyForce::force(const Fluid& fluid, const Vec3& gravity, double d, const Vec3&, const FluidSample&) const {
  return -fluid.density * sphere_volume_of_diameter(d) * gravity;
}

std::unique_ptr<FluidForce> make_fluid_force(const std::string& name) {
  if (name == "difelice_drag") return std::make_unique<DragForce>(std::make_unique<DiFeliceDrag>());
  if (name == "gidaspow_drag") return std::make_unique<GridDragForce>();
  if (name == "schiller_naumann_drag") return std::make_unique<DragForce>(std::make_unique<SchillerNaumannDrag>());
  if (name == "pressure_gradient") return std::make_unique<PressureGradientForce>();
  if (name == "buoyancy") return std::make_unique<BuoyancyForce>();
  throw std::invalid_argument("unknown fluid force '" + name + "'");
}

std::vector<std::unique_ptr<FluidForce>> make_fluid_forces(const std::vector<std::string>& names) {
  std::vector<std::unique_ptr<FluidForce>> forces;
  for (const auto& n : names) forces.push_back(make_fluid_force(n));
  return forces;
}

}  // namespace frostwall::pore_water
