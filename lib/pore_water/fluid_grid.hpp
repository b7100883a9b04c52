// The pore water of the CFD-DEM model on a coarse regular grid of cells
// (the paper's: 20^3 cells of 1 cm, ~15 grains each). Inertia-free,
// volume-averaged flow, the PFC3D CFD module's form:
//  - momentum, per cell: -grad p = beta U_slip, U_slip = U - eps v_p, with
//    U the superficial (Darcy) water velocity, v_p the cell's mean grain
//    velocity, beta = bed_gradient(eps, d, |U_slip|) / |U_slip|
//    (pore_water/bed_resistance.hpp);
//  - continuity of the mixture of incompressible water and grains:
//    div(U + (1 - eps) v_p) = div(U_slip + v_p) = 0.
// p is the EXCESS pressure over hydrostatic: gravity does not appear here,
// so the caller must apply buoyancy (rho_f g times the grain volume) to the
// grains as a separate force, besides the drag and -grad p times volume.
// Grains never cross the box faces (the DEM walls hold them): the grain
// flux through every box face is zero.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "pore_water/drag_law.hpp"

namespace frostwall::pore_water {

// The box [low, high] split into cells[0] x cells[1] x cells[2] cells;
// cell (i, j, k) is number i + nx (j + ny k).
struct GridShape {
  Vec3 low = Vec3::Zero(), high = Vec3::Ones();
  std::array<int, 3> cells{1, 1, 1};

  double cell_size(int axis) const { return (high[axis] - low[axis]) / cells[axis]; }
  double cell_volume() const { return cell_size(0) * cell_size(1) * cell_size(2); }
  // Area of a cell face normal to the axis.
  double face_area(int axis) const { return cell_volume() / cell_size(axis); }
  int index(int i, int j, int k) const { return i + cells[0] * (j + cells[1] * k); }
  int count() const { return cells[0] * cells[1] * cells[2]; }
  Vec3 centre(int i, int j, int k) const;
  // The cell holding x (clamped into the box).
  int cell_of(const Vec3& x) const;
};

// Box faces 0..5: x-, x+, y-, y+, z-, z+ (face = 2 axis + side).
enum class FaceKind { wall, inflow_velocity, pressure };
struct FaceCondition {
  FaceKind kind = FaceKind::wall;
  // wall: unused (no flow). inflow_velocity: superficial velocity INTO the
  // domain, m/s, uniform over the face (mixture flux; grains do not cross).
  // pressure: the face's fixed excess pressure, Pa, with a half-cell
  // resistance between the face and the cell centre.
  double value = 0.0;
};

struct FluidSample {
  double porosity = 1.0;
  Vec3 fluid_velocity = Vec3::Zero();        // interstitial, u_f = U / eps
  Vec3 superficial_velocity = Vec3::Zero();  // U
  Vec3 pressure_gradient = Vec3::Zero();     // of the excess pressure, Pa/m
  // The grid's own drag (Gidaspow: its Ergun/Wen-Yu resistance) per grain
  // volume, K (drag_velocity - v), with K and K u_f interpolated from the
  // cells by the weights the grains were deposited with: the grains of a
  // uniform bed then take exactly the momentum its water loses.
  double drag_coefficient = 0.0;      // K, kg/(m3 s)
  Vec3 drag_velocity = Vec3::Zero();  // m/s
};

struct SolveReport {
  int picard_iterations = 0;
  int linear_iterations = 0;  // summed over the Picard iterations
  double residual = 0.0;      // last linear solve's relative residual
  bool converged = false;     // beta settled and every linear solve converged
};

struct PressureSolver;  // the CG and its preconditioner's ordering, kept between solves

class FluidGrid {
 public:
  // Throws std::invalid_argument for an empty box, a bad porosity range or
  // no pressure face (the pressure would be fixed only up to a constant).
  FluidGrid(GridShape shape, std::array<FaceCondition, 6> faces, Fluid fluid, double default_diameter,
            double min_porosity, double max_porosity = 1.0);
  ~FluidGrid();
  FluidGrid(FluidGrid&&) noexcept;

  // Grain deposition in three steps, so that an MPI caller can Allreduce
  // the raw sums (deposits()) between add_grain and finish_grains.
  void clear_grains();
  // Spreads the grain's volume with a tent kernel one cell wide (cloud in
  // cell) over the up-to-8 cells whose centres surround it; a share that
  // would fall outside the box goes to the mirror cell inside, so the whole
  // volume stays in the box. A grain outside the box counts as on its face.
  void add_grain(const Vec3& x, double diameter, const Vec3& velocity);
  // Per cell, contiguous: grain volume, volume x velocity (3), volume x d.
  static constexpr int deposit_fields = 5;
  std::vector<double>& deposits() { return deposits_; }
  // Porosity (clamped), mean grain velocity and diameter of every cell.
  void finish_grains();

  void set_face(int face, FaceCondition c);  // throws as the constructor
  // Picard iterations on beta (warm-started from the last solution) with a
  // conjugate-gradient solve for the pressure in each.
  SolveReport solve(double tolerance = 1e-10, double picard_tolerance = 1e-6, int max_picard = 100);

  const GridShape& shape() const { return shape_; }
  const std::vector<double>& porosity() const { return porosity_; }
  const std::vector<double>& raw_porosity() const { return raw_porosity_; }
  const std::vector<Vec3>& grain_velocity() const { return grain_velocity_; }
  const std::vector<double>& grain_diameter() const { return diameter_; }
  const std::vector<double>& resistance() const { return beta_; }  // beta, Pa s/m2
  const std::vector<double>& pressure() const { return pressure_; }
  // U at the cell centres: the mean of the two opposite faces' mixture
  // flux less the cell's grain flux (1 - eps) v_p.
  std::vector<Vec3> superficial_velocity() const;
  // Cell-centre values interpolated trilinearly (clamped to the outermost
  // centres); the pressure gradient at a centre is the mean of its faces'.
  FluidSample sample(const Vec3& x) const;

  // Mixture flow, m3/s: in through the inflow faces, out through the
  // pressure faces (net), and the largest |net outflow| of one cell.
  double inflow() const;
  double outflow() const;
  double largest_cell_imbalance() const;
  // Mean pressure on a box face: the given value on a pressure face, else
  // the adjacent centres' pressure carried half a cell with the face gradient.
  double face_pressure(int face) const;

 private:
  void check_faces() const;
  void update_resistance(std::vector<double>& beta) const;
  void update_faces();
  // One Picard step's pressure solve with the present beta (warm started
  // from the last pressure), then the faces' flows; false when the linear
  // solver failed. Adds its iterations and residual to `report`.
  bool solve_pressure(double linear_tolerance, SolveReport& report);
  // The next beta from the last solve's slip, damped where it swings
  // (`damp`: from the second step on; last_step: each cell's last change),
  // and the change it makes, relative to the largest pressure gradient.
  double next_resistance(std::vector<double>& next, std::vector<double>& last_step, bool damp) const;
  void update_drag();
  double cell_outflow(int cell) const;
  Vec3 centre_velocity(int cell) const;

  GridShape shape_;
  std::array<FaceCondition, 6> faces_;
  Fluid fluid_;
  double default_diameter_, min_porosity_, max_porosity_;
  double beta_floor_;
  std::vector<double> drag_coefficient_;    // K per cell, after a solve
  std::unique_ptr<PressureSolver> solver_;  // the matrix's pattern never changes: ordered once
  std::vector<double> deposits_;
  std::vector<double> raw_porosity_, porosity_, diameter_, beta_, pressure_;
  std::vector<Vec3> grain_velocity_;
  // Per axis, per face normal to it: the slip flux U_slip, the grain
  // velocity and the pressure gradient, all along the axis.
  std::array<std::vector<double>, 3> slip_, grain_, gradient_;
};

}  // namespace frostwall::pore_water
