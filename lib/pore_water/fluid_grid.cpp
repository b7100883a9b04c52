#include "pore_water/fluid_grid.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pore_water/bed_resistance.hpp"
#include "pore_water/grid_indexing.hpp"

namespace frostwall::pore_water {

struct PressureSolver {
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper, Eigen::IncompleteCholesky<double>>
      cg;
};

using namespace grid;

Vec3 GridShape::centre(int i, int j, int k) const {
  const Cell p{i, j, k};
  Vec3 x;
  for (int a = 0; a < 3; ++a) x[a] = low[a] + (p[a] + 0.5) * cell_size(a);
  return x;
}

int GridShape::cell_of(const Vec3& x) const {
  Cell p;
  for (int a = 0; a < 3; ++a) p[a] = std::clamp(static_cast<int>((x[a] - low[a]) / cell_size(a)), 0, cells[a] - 1);
  return flat(*this, p);
}

FluidGrid::FluidGrid(GridShape shape, std::array<FaceCondition, 6> faces, Fluid fluid, double default_diameter,
                     double min_porosity, double max_porosity)
    : shape_(shape),
      faces_(faces),
      fluid_(fluid),
      default_diameter_(default_diameter),
      min_porosity_(min_porosity),
      max_porosity_(max_porosity) {
  for (int a = 0; a < 3; ++a)
    if (shape_.cells[a] < 1 || !(shape_.high[a] > shape_.low[a]))
      throw std::invalid_argument("fluid grid: the box needs a positive size and at least one cell per axis");
  if (!(min_porosity_ > 0.0 && min_porosity_ <= max_porosity_ && max_porosity_ <= 1.0))
    throw std::invalid_argument("fluid grid: porosity limits must satisfy 0 < min <= max <= 1");
  if (!(default_diameter_ > 0.0)) throw std::invalid_argument("fluid grid: the default diameter must be positive");
  check_faces();
  // The Darcy-like resistance of a channel one cell wide (plane Poiseuille,
  // -dp/dx = 12 mu U / h^2): keeps grain-free cells, where the bed laws
  // give no resistance, solvable.
  const double h = std::min({shape_.cell_size(0), shape_.cell_size(1), shape_.cell_size(2)});
  beta_floor_ = 12.0 * fluid_.viscosity / (h * h);
  const int n = shape_.count();
  pressure_.assign(n, 0.0);
  beta_.assign(n, beta_floor_);
  for (int a = 0; a < 3; ++a) {
    Cell d = shape_.cells;
    d[a] += 1;
    slip_[a].assign(d[0] * d[1] * d[2], 0.0);
    grain_[a].assign(slip_[a].size(), 0.0);
    gradient_[a].assign(slip_[a].size(), 0.0);
  }
  clear_grains();
  finish_grains();
}

void FluidGrid::check_faces() const {
  if (std::none_of(faces_.begin(), faces_.end(), [](const FaceCondition& f) { return f.kind == FaceKind::pressure; }))
    throw std::invalid_argument("fluid grid: at least one box face must have a fixed pressure");
}

void FluidGrid::set_face(int face, FaceCondition c) {
  if (face < 0 || face > 5) throw std::invalid_argument("fluid grid: face index must be 0..5");
  const FaceCondition old = faces_[face];
  faces_[face] = c;
  try {
    check_faces();
  } catch (...) {
    faces_[face] = old;
    throw;
  }
}

// ---- grains ----------------------------------------------------------------

void FluidGrid::clear_grains() { deposits_.assign(std::size_t(deposit_fields) * shape_.count(), 0.0); }

void FluidGrid::add_grain(const Vec3& x, double diameter, const Vec3& velocity) {
  const double volume = std::numbers::pi * diameter * diameter * diameter / 6.0;
  // Per axis: the two cells whose centres bracket the grain and their tent
  // weights; a cell past the wall is folded onto its mirror, the edge cell.
  std::array<std::array<int, 2>, 3> cell;
  std::array<std::array<double, 2>, 3> weight;
  for (int a = 0; a < 3; ++a) {
    const int n = shape_.cells[a];
    const double s = (std::clamp(x[a], shape_.low[a], shape_.high[a]) - shape_.low[a]) / shape_.cell_size(a) - 0.5;
    const int i0 = std::clamp(int(std::floor(s)), -1, n - 1);
    const double f = s - i0;
    cell[a] = {std::max(i0, 0), std::min(i0 + 1, n - 1)};
    weight[a] = {1.0 - f, f};
  }
  for (int u = 0; u < 2; ++u)
    for (int v = 0; v < 2; ++v)
      for (int w = 0; w < 2; ++w) {
        const double share = volume * weight[0][u] * weight[1][v] * weight[2][w];
        if (share == 0.0) continue;
        double* d = &deposits_[std::size_t(deposit_fields) * shape_.index(cell[0][u], cell[1][v], cell[2][w])];
        d[0] += share;
        for (int a = 0; a < 3; ++a) d[1 + a] += share * velocity[a];
        d[4] += share * diameter;
      }
}

void FluidGrid::finish_grains() {
  const int n = shape_.count();
  const double cell_volume = shape_.cell_volume();
  raw_porosity_.resize(n);
  porosity_.resize(n);
  diameter_.resize(n);
  grain_velocity_.resize(n);
  for (int c = 0; c < n; ++c) {
    const double* d = &deposits_[std::size_t(deposit_fields) * c];
    raw_porosity_[c] = 1.0 - d[0] / cell_volume;
    porosity_[c] = std::clamp(raw_porosity_[c], min_porosity_, max_porosity_);
    if (d[0] > 0.0) {
      grain_velocity_[c] = Vec3(d[1], d[2], d[3]) / d[0];
      diameter_[c] = d[4] / d[0];
    } else {
      grain_velocity_[c] = Vec3::Zero();
      diameter_[c] = default_diameter_;
    }
  }
}

// ---- solve -------------------------------------------------------------------

// beta of every cell from the slip at its centre (the mean of its faces').
void FluidGrid::update_resistance(std::vector<double>& beta) const {
  beta.resize(shape_.count());
  for (int c = 0; c < shape_.count(); ++c) {
    const double speed = std::max(face_mean(shape_, slip_, c).norm(), tiny_speed);
    beta[c] = std::max(bed_gradient(fluid_, porosity_[c], diameter_[c], speed) / speed, beta_floor_);
  }
}

// Face fields from the pressure and beta: gradient, slip = -gradient / beta_f
// (beta_f the mean of the two cells': resistances in series add), and grains.
void FluidGrid::update_faces() {
  for (int c = 0; c < shape_.count(); ++c) {
    const Cell p = coords(shape_, c);
    for (int a = 0; a < 3; ++a) {
      const double h = shape_.cell_size(a);
      for (int side = 0; side < 2; ++side) {
        const int f = face_id(shape_, a, p, side);
        const bool boundary = (side == 0 && p[a] == 0) || (side == 1 && p[a] == shape_.cells[a] - 1);
        if (!boundary) {
          if (side == 0) continue;  // each interior face once, from its lower cell
          Cell q = p;
          q[a] += 1;
          const int nb = flat(shape_, q);
          gradient_[a][f] = (pressure_[nb] - pressure_[c]) / h;
          slip_[a][f] = -gradient_[a][f] / (0.5 * (beta_[c] + beta_[nb]));
          grain_[a][f] = 0.5 * (grain_velocity_[c][a] + grain_velocity_[nb][a]);
          continue;
        }
        const FaceCondition& bc = faces_[2 * a + side];
        const double inward = side == 0 ? 1.0 : -1.0;  // axis direction into the box
        grain_[a][f] = 0.0;
        if (bc.kind == FaceKind::wall) {
          slip_[a][f] = gradient_[a][f] = 0.0;
        } else if (bc.kind == FaceKind::inflow_velocity) {
          slip_[a][f] = inward * bc.value;
          gradient_[a][f] = -beta_[c] * slip_[a][f];
        } else {
          gradient_[a][f] = inward * (pressure_[c] - bc.value) / (0.5 * h);
          slip_[a][f] = -gradient_[a][f] / beta_[c];
        }
      }
    }
  }
}

namespace {

// The pressure equation with the resistance beta: per cell, the sum over
// its faces of the outward mixture flux = 0, the slip part T (p_c - p_nb)
// with T = A / (h beta_f) in the matrix, the grains' flux and the fixed
// inflows and pressures of the box's faces in the right-hand side.
void assemble_pressure(const GridShape& shape, const std::array<FaceCondition, 6>& faces,
                       const std::vector<double>& beta, const std::vector<Vec3>& grain_velocity,
                       Eigen::SparseMatrix<double>& K, Eigen::VectorXd& rhs) {
  const int n = shape.count();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(7 * std::size_t(n));
  rhs = Eigen::VectorXd::Zero(n);
  for (int c = 0; c < n; ++c) {
    const Cell pc = coords(shape, c);
    for (int a = 0; a < 3; ++a) {
      const double h = shape.cell_size(a), area = shape.face_area(a);
      if (pc[a] + 1 < shape.cells[a]) {
        Cell q = pc;
        q[a] += 1;
        const int nb = flat(shape, q);
        const double T = area / (h * 0.5 * (beta[c] + beta[nb]));
        entries.emplace_back(c, c, T);
        entries.emplace_back(nb, nb, T);
        entries.emplace_back(c, nb, -T);
        entries.emplace_back(nb, c, -T);
        const double grains = area * 0.5 * (grain_velocity[c][a] + grain_velocity[nb][a]);
        rhs[c] -= grains;
        rhs[nb] += grains;
      }
      for (int side = 0; side < 2; ++side) {
        if (pc[a] != (side == 0 ? 0 : shape.cells[a] - 1)) continue;
        const FaceCondition& bc = faces[2 * a + side];
        if (bc.kind == FaceKind::inflow_velocity) {
          rhs[c] += area * bc.value;
        } else if (bc.kind == FaceKind::pressure) {
          const double T = area / (0.5 * h * beta[c]);
          entries.emplace_back(c, c, T);
          rhs[c] += T * bc.value;
        }
      }
    }
  }
  K.resize(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
}

}  // namespace

bool FluidGrid::solve_pressure(double linear_tolerance, SolveReport& report) {
  const int n = shape_.count();
  Eigen::SparseMatrix<double> K;
  Eigen::VectorXd rhs;
  assemble_pressure(shape_, faces_, beta_, grain_velocity_, K, rhs);
  if (!solver_) {
    solver_ = std::make_unique<PressureSolver>();
    solver_->cg.analyzePattern(K);
  }
  auto& cg = solver_->cg;
  cg.setTolerance(linear_tolerance);
  cg.factorize(K);
  // Warm start from the last pressure.
  Eigen::VectorXd p = Eigen::Map<const Eigen::VectorXd>(pressure_.data(), n);
  bool linear_ok = cg.info() == Eigen::Success;
  if (linear_ok) {
    p = cg.solveWithGuess(rhs, p);
    linear_ok = cg.info() == Eigen::Success;
  }
  report.linear_iterations += int(cg.iterations());
  report.residual = cg.error();
  std::copy(p.data(), p.data() + n, pressure_.begin());
  update_faces();
  return linear_ok;
}

double FluidGrid::next_resistance(std::vector<double>& next, std::vector<double>& last_step, bool damp) const {
  const int n = shape_.count();
  update_resistance(next);
  // Where beta swings about the answer (the inertial, Forchheimer term
  // rules: beta ~ |U| and plain Picard gives beta_k+1 = b G / beta_k),
  // take the geometric mean of the old and the new, which lands on it;
  // elsewhere (Darcy-like cells) plain Picard converges in a step or two.
  for (int c = 0; c < n; ++c) {
    const double step = next[c] - beta_[c];
    if (damp && step * last_step[c] < 0.0) next[c] = std::sqrt(next[c] * beta_[c]);
    last_step[c] = next[c] - beta_[c];
  }
  // The change in each cell's pressure gradient beta |U_slip| that the
  // new beta makes, over the largest gradient in the grid: cells with
  // next to no flow do not hold the iteration up.
  double change = 0.0, largest = 0.0;
  for (int c = 0; c < n; ++c) {
    const double speed = face_mean(shape_, slip_, c).norm();
    largest = std::max(largest, beta_[c] * speed);
    change = std::max(change, std::abs(next[c] - beta_[c]) * speed);
  }
  return largest > 0.0 ? change / largest : 0.0;
}

SolveReport FluidGrid::solve(double tolerance, double picard_tolerance, int max_picard) {
  SolveReport report;
  // Warm start: beta from the last solution's slip, with the current grains.
  update_resistance(beta_);
  std::vector<double> next, last_step(shape_.count(), 0.0);
  // Inexact Picard: early solves only as tight as beta is settled, and one
  // last solve at the full tolerance with the final beta (the mass balance).
  double linear_tolerance = std::max(tolerance, 1e-6);
  bool final_pass = false;
  for (int it = 1; it <= max_picard + 1; ++it) {
    report.picard_iterations = it;
    if (!solve_pressure(linear_tolerance, report)) return report;
    if (final_pass) {
      report.converged = true;
      break;
    }
    const double change = next_resistance(next, last_step, it > 1);
    // Stop with the beta the pressure was solved with, so the face fluxes
    // balance exactly.
    if (change < picard_tolerance || it >= max_picard) {
      if (linear_tolerance <= tolerance) {
        report.converged = change < picard_tolerance;
        break;
      }
      final_pass = true;  // the same beta, solved tightly
      linear_tolerance = tolerance;
      continue;
    }
    beta_.swap(next);
    linear_tolerance = std::max(tolerance, std::min(1e-6, 1e-3 * change));
  }
  update_drag();
  return report;
}

// K = eps^2 (-dp/dx per unit solid fraction) / |U_slip|, without the
// floor: the drag per grain volume is K (u_f - v), and over a cell's
// grains it sums to eps beta U_slip per cell volume, the momentum the
// water's pressure loses there less the -grad p the grains take directly.
void FluidGrid::update_drag() {
  drag_coefficient_.resize(shape_.count());
  for (int c = 0; c < shape_.count(); ++c) {
    const double e = porosity_[c];
    if (beta_[c] > beta_floor_ && e < 0.999) {
      // The beta the pressure was solved with, so that the grains take
      // exactly what the water lost, however far Picard went.
      drag_coefficient_[c] = e * e * beta_[c] / (1.0 - e);
    } else {  // nearly no grains, or the floor: the law itself at this slip
      const double speed = std::max(face_mean(shape_, slip_, c).norm(), tiny_speed);
      drag_coefficient_[c] = e * e * bed_gradient_per_solid(fluid_, e, diameter_[c], speed) / speed;
    }
  }
}

FluidGrid::~FluidGrid() = default;
FluidGrid::FluidGrid(FluidGrid&&) noexcept = default;

}  // namespace frostwall::pore_water
