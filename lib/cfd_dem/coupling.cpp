#include "cfd_dem/coupling.hpp"

#include "dem/packing.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mpi.h>

#include "particles/sphere.hpp"

namespace frostwall::cfd_dem {

namespace {

using pore_water::Vec3;

pore_water::GridShape grid_shape(const project::CfdDem& c) {
  pore_water::GridShape s;
  s.low = Vec3(c.box.low[0], c.box.low[1], c.box.low[2]);
  s.high = Vec3(c.box.high[0], c.box.high[1], c.box.high[2]);
  s.cells = c.fluid.cells;
  return s;
}

int kind_index(pore_water::ForceKind k) { return static_cast<int>(k); }

}  // namespace

std::array<pore_water::FaceCondition, 6> fluid_faces(const project::CfdDem& c, double inflow_velocity) {
  using pore_water::FaceKind;
  std::array<pore_water::FaceCondition, 6> faces{};
  if (c.flow) {
    const auto& f = *c.flow;
    faces[static_cast<int>(f.inflow)] = f.inflow_pressure
                                            ? pore_water::FaceCondition{FaceKind::pressure, *f.inflow_pressure}
                                            : pore_water::FaceCondition{FaceKind::inflow_velocity, inflow_velocity};
    faces[static_cast<int>(f.outflow)] = {FaceKind::pressure, f.outflow_pressure};
    return faces;
  }
  // Still water: the surface is open where gravity points away from.
  const int axis = std::max(0, project::gravity_axis(c));
  faces[2 * axis + (c.gravity[axis] <= 0.0 ? 1 : 0)] = {FaceKind::pressure, 0.0};
  return faces;
}

CfdDemCoupling::CfdDemCoupling(const project::CfdDem& c, dem::LammpsSession& lammps)
    : c_(c),
      lammps_(lammps),
      grid_(grid_shape(c), fluid_faces(c, 0.0), {c.fluid.density, c.fluid.viscosity}, c.grains.mean_diameter(),
            c.fluid.min_porosity),
      forces_(pore_water::make_fluid_forces(c.forces)) {
  size_by_id();
  lammps_.set_external_force(dem::fluid_fix,
                             [this](int n, const int* ids, double**, double** force) { apply(n, ids, force); });
}

void CfdDemCoupling::apply(int n, const int* ids, double** force) const {
  // Before the first update every held value is zero.
  double** v = lammps_.velocity();
  for (int i = 0; i < n; ++i) {
    const auto& f = held_[ids[i]];
    const double K = drag_k_[ids[i]];
    const auto& u = drag_u_[ids[i]];
    for (int k = 0; k < 3; ++k) force[i][k] = f[k] + K * (u[k] - v[i][k]);
  }
}

pore_water::SolveReport CfdDemCoupling::update(double inflow_velocity) {
  const auto start = std::chrono::steady_clock::now();
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  double** x = lammps_.position();
  double** v = lammps_.velocity();
  const double* r = lammps_.radius();
  grid_.clear_grains();
  for (int i = 0; i < n; ++i)
    grid_.add_grain(Vec3(x[i][0], x[i][1], x[i][2]), 2.0 * r[i], Vec3(v[i][0], v[i][1], v[i][2]));
  auto& sums = grid_.deposits();
  if (lammps_.ranks() > 1)
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  grid_.finish_grains();
  if (c_.flow && !c_.flow->inflow_pressure)
    grid_.set_face(static_cast<int>(c_.flow->inflow), {pore_water::FaceKind::inflow_velocity, inflow_velocity});
  // Picard until beta moves the largest pressure gradient by 1e-3 of
  // itself (the drag laws themselves are good to some 10 %); the flow's
  // mass balance holds to the linear solver's 1e-10 whatever beta stopped at.
  const auto report = grid_.solve(1e-10, 1e-3);
  const pore_water::Fluid fluid{c_.fluid.density, c_.fluid.viscosity};
  const Vec3 g(c_.gravity[0], c_.gravity[1], c_.gravity[2]);
  const bool semi_implicit = c_.coupling.drag == project::DragCoupling::semi_implicit;
  shortest_relaxation_.fill(std::numeric_limits<double>::infinity());
  for (int i = 0; i < n; ++i) {
    const Vec3 xi(x[i][0], x[i][1], x[i][2]), vi(v[i][0], v[i][1], v[i][2]);
    const auto sample = grid_.sample(xi);
    const int id = ids[i];
    auto& kinds = by_kind_[id];
    kinds = {};
    std::array<double, 3> total{}, held{};
    double K = 0.0;
    Vec3 u = Vec3::Zero();
    for (const auto& force : forces_) {
      const Vec3 f = force->force(fluid, g, 2.0 * r[i], vi, sample);
      const auto linear = force->linear_drag(fluid, 2.0 * r[i], vi, sample);
      const bool implicit = semi_implicit && linear;
      if (linear) K += linear->coefficient;
      if (implicit) u += linear->coefficient * linear->velocity;  // K-weighted: one K (u - v) for all drags
      for (int k = 0; k < 3; ++k) {
        kinds[kind_index(force->kind())][k] += f[k], total[k] += f[k];
        if (!implicit) held[k] += f[k];
      }
    }
    const double mass = c_.grains.density * particles::sphere_volume_of_diameter(2.0 * r[i]);
    if (K > 0.0) shortest_relaxation_[0] = std::min(shortest_relaxation_[0], mass / K);
    // beta = K_v (1 - eps) / eps^2 with K_v the grid's drag per grain volume.
    const double eps = sample.porosity;
    if (sample.drag_coefficient > 0.0 && eps < 1.0)
      shortest_relaxation_[1] =
          std::min(shortest_relaxation_[1], c_.grains.density * eps * eps / (sample.drag_coefficient * (1.0 - eps)));
    shown_[id] = total;
    held_[id] = held;
    drag_k_[id] = semi_implicit && K > 0.0 ? K : 0.0;
    for (int k = 0; k < 3; ++k) drag_u_[id][k] = drag_k_[id] > 0.0 ? u[k] / K : 0.0;
  }
  if (lammps_.ranks() > 1)
    MPI_Allreduce(MPI_IN_PLACE, shortest_relaxation_.data(), 2, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  coupling_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void CfdDemCoupling::size_by_id() {
  // Grains are never created after the start (this is called once, when
  // they have been read), and deleted ones keep their ids: the largest id
  // any rank holds bounds them all.
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  int largest = 0;
  for (int i = 0; i < n; ++i) largest = std::max(largest, ids[i]);
  if (lammps_.ranks() > 1) MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  const std::size_t size = static_cast<std::size_t>(largest) + 1;
  if (held_.size() < size) {
    held_.resize(size), shown_.resize(size), by_kind_.resize(size);
    drag_k_.resize(size), drag_u_.resize(size);
  }
}

void CfdDemCoupling::hold_buoyancy_only() {
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  const double* r = lammps_.radius();
  const pore_water::BuoyancyForce buoyancy;
  const pore_water::Fluid fluid{c_.fluid.density, c_.fluid.viscosity};
  const Vec3 g(c_.gravity[0], c_.gravity[1], c_.gravity[2]);
  for (int i = 0; i < n; ++i) {
    const Vec3 f = buoyancy.force(fluid, g, 2.0 * r[i], Vec3::Zero(), pore_water::FluidSample{});
    held_[ids[i]] = shown_[ids[i]] = {f[0], f[1], f[2]};
    drag_k_[ids[i]] = 0.0;
    by_kind_[ids[i]] = {};
    by_kind_[ids[i]][kind_index(pore_water::ForceKind::buoyancy)] = held_[ids[i]];
  }
}

const std::array<std::array<double, 3>, 3>& CfdDemCoupling::force_by_kind(int id) const {
  static const std::array<std::array<double, 3>, 3> none{};
  return static_cast<std::size_t>(id) < by_kind_.size() ? by_kind_[id] : none;
}

void CfdDemCoupling::advance(long steps) { lammps_.run(steps); }

std::array<double, 3> CfdDemCoupling::fluid_force(int id) const {
  return static_cast<std::size_t>(id) < shown_.size() ? shown_[id] : std::array<double, 3>{};
}

CfdDemCoupling::Motion CfdDemCoupling::motion() const {
  const int n = lammps_.local_count();
  double** v = lammps_.velocity();
  const double* r = lammps_.radius();
  double sums[2] = {0.0, 0.0}, fastest = 0.0;  // energy, mass; the largest v^2
  for (int i = 0; i < n; ++i) {
    const double v2 = v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2];
    const double mass = c_.grains.density * particles::sphere_volume_of_diameter(2.0 * r[i]);
    sums[0] += 0.5 * mass * v2, sums[1] += mass;
    fastest = std::max(fastest, v2);
  }
  if (lammps_.ranks() > 1) {
    MPI_Allreduce(MPI_IN_PLACE, sums, 2, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &fastest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  }
  return {sums[0], std::sqrt(fastest), sums[1]};
}

double CfdDemCoupling::lost(const double* x) const { return dem::in_cavity(c_, x) ? 1.0 : 0.0; }

GrainTotals CfdDemCoupling::totals() const {
  GrainTotals t;
  const int n = lammps_.local_count();
  const int* ids = lammps_.ids();
  double** x = lammps_.position();
  double** v = lammps_.velocity();
  const double* r = lammps_.radius();
  const double* contacts = lammps_.contacts();
  for (int i = 0; i < n; ++i) {
    const double volume = particles::sphere_volume_of_diameter(2.0 * r[i]);
    t.count += 1.0;
    t.in_cavity += lost(x[i]);
    t.volume += volume;
    t.contacts += contacts ? contacts[i] : 0.0;
    for (int k = 0; k < 3; ++k) {
      t.position_sum[k] += volume * x[i][k];
      t.velocity_sum[k] += volume * v[i][k];
    }
    if (static_cast<std::size_t>(ids[i]) < by_kind_.size())
      for (int kind = 0; kind < 3; ++kind)
        for (int k = 0; k < 3; ++k) t.force[kind][k] += by_kind_[ids[i]][kind][k];
  }
  if (lammps_.ranks() > 1)
    MPI_Allreduce(MPI_IN_PLACE, &t, sizeof(GrainTotals) / sizeof(double), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  t.contacts *= 0.5;  // each contact is counted by both its grains
  return t;
}

}  // namespace frostwall::cfd_dem
