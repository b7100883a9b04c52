// A classical finite-element solution of the PD paper's plate (section
// 3.2), independent of frostwall's particles: P1 triangles on a structured
// N x N mesh of the 1 cm square (each cell cut along its diagonal),
//  - heat: lumped-mass P1, backward Euler, T = 1 C held on the top and
//    right edges, 10 C initially, insulated left and bottom;
//  - plane-strain thermo-elasticity at chosen times: sigma = lambda tr(eps) I
//    + 2 mu eps - (3 lambda + 2 mu) alpha dT I (so a free body expands by
//    (1 + nu) alpha dT in plane), rollers on the left (u_x = 0) and bottom
//    (u_y = 0), top and right free; dT per element the mean of its nodes.
// Returns the displacement at named points (nodes) at the requested times.
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <array>
#include <cmath>
#include <vector>

namespace frostwall::test {

struct PlateFeResult {
  std::vector<std::array<double, 2>> A, B, C;  // (ux, uy) per requested time
};

inline PlateFeResult plate_fe(int N, double dt, const std::vector<double>& times) {
  const double L = 0.01, h = L / N, k = 1.0, rho_c = 1800.0 * 1688.0;
  const double E = 25.7e9, nu = 0.25, alpha = 1.8e-5;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const int n = (N + 1) * (N + 1);
  auto node = [&](int i, int j) { return j * (N + 1) + i; };
  std::vector<std::array<int, 3>> tri;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) {
      tri.push_back({node(i, j), node(i + 1, j), node(i + 1, j + 1)});
      tri.push_back({node(i, j), node(i + 1, j + 1), node(i, j + 1)});
    }
  auto xy = [&](int a) { return std::array<double, 2>{(a % (N + 1)) * h, (a / (N + 1)) * h}; };
  // Gradients of the three shape functions of a triangle (constant), area.
  auto gradients = [&](const std::array<int, 3>& t, double& area) {
    const auto p0 = xy(t[0]), p1 = xy(t[1]), p2 = xy(t[2]);
    const double det = (p1[0] - p0[0]) * (p2[1] - p0[1]) - (p2[0] - p0[0]) * (p1[1] - p0[1]);
    area = 0.5 * std::abs(det);
    std::array<std::array<double, 2>, 3> g;
    g[0] = {(p1[1] - p2[1]) / det, (p2[0] - p1[0]) / det};
    g[1] = {(p2[1] - p0[1]) / det, (p0[0] - p2[0]) / det};
    g[2] = {(p0[1] - p1[1]) / det, (p1[0] - p0[0]) / det};
    return g;
  };
  // ---- heat: (M/dt + K) T_new = M/dt T_old, Dirichlet rows on top/right.
  std::vector<Eigen::Triplet<double>> kt;
  std::vector<double> mass(n, 0.0);
  for (const auto& t : tri) {
    double area;
    const auto g = gradients(t, area);
    for (int a = 0; a < 3; ++a) {
      mass[t[a]] += rho_c * area / 3.0;
      for (int b = 0; b < 3; ++b) kt.emplace_back(t[a], t[b], k * area * (g[a][0] * g[b][0] + g[a][1] * g[b][1]));
    }
  }
  auto held = [&](int a) {
    const auto p = xy(a);
    return p[0] > L - 1e-12 || p[1] > L - 1e-12;
  };
  std::vector<Eigen::Triplet<double>> at;
  for (const auto& e : kt)
    if (!held(e.row())) at.emplace_back(e.row(), e.col(), dt * e.value());
  for (int a = 0; a < n; ++a) at.emplace_back(a, a, held(a) ? 1.0 : mass[a]);
  Eigen::SparseMatrix<double> Ah(n, n);
  Ah.setFromTriplets(at.begin(), at.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> heat(Ah);
  Eigen::VectorXd T = Eigen::VectorXd::Constant(n, 10.0);
  for (int a = 0; a < n; ++a)
    if (held(a)) T[a] = 1.0;

  // ---- elasticity: K u = f(T), dofs 2a, 2a+1; rollers remove u_x at x = 0, u_y at y = 0.
  std::vector<Eigen::Triplet<double>> ku;
  for (const auto& t : tri) {
    double area;
    const auto g = gradients(t, area);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        // B_a^T D B_b for plane strain (D from lambda, mu).
        const double xx = (lambda + 2 * mu) * g[a][0] * g[b][0] + mu * g[a][1] * g[b][1];
        const double yy = (lambda + 2 * mu) * g[a][1] * g[b][1] + mu * g[a][0] * g[b][0];
        const double xy_ = lambda * g[a][0] * g[b][1] + mu * g[a][1] * g[b][0];
        const double yx = lambda * g[a][1] * g[b][0] + mu * g[a][0] * g[b][1];
        ku.emplace_back(2 * t[a], 2 * t[b], area * xx);
        ku.emplace_back(2 * t[a] + 1, 2 * t[b] + 1, area * yy);
        ku.emplace_back(2 * t[a], 2 * t[b] + 1, area * xy_);
        ku.emplace_back(2 * t[a] + 1, 2 * t[b], area * yx);
      }
  }
  auto fixed_dof = [&](int d) {
    const auto p = xy(d / 2);
    return (d % 2 == 0 && p[0] < 1e-12) || (d % 2 == 1 && p[1] < 1e-12);
  };
  std::vector<Eigen::Triplet<double>> kc;
  for (const auto& e : ku)
    if (!fixed_dof(e.row()) && !fixed_dof(e.col())) kc.push_back(e);
  for (int d = 0; d < 2 * n; ++d)
    if (fixed_dof(d)) kc.emplace_back(d, d, 1.0);
  Eigen::SparseMatrix<double> Ku(2 * n, 2 * n);
  Ku.setFromTriplets(kc.begin(), kc.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> elastic(Ku);

  const int A = node(N, N), B = node(N, N / 2), C = node(N / 2, N / 2);
  PlateFeResult r;
  double t = 0.0;
  for (double target : times) {
    while (t < target - 1e-9) {
      Eigen::VectorXd rhs(n);
      for (int a = 0; a < n; ++a) rhs[a] = held(a) ? 1.0 : mass[a] * T[a];
      T = heat.solve(rhs);
      t += dt;
    }
    Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
    for (const auto& tr : tri) {
      double area;
      const auto g = gradients(tr, area);
      const double dT = (T[tr[0]] + T[tr[1]] + T[tr[2]]) / 3.0 - 10.0;
      const double s = (3 * lambda + 2 * mu) * alpha * dT;  // thermal stress, isotropic
      for (int a = 0; a < 3; ++a) {
        f[2 * tr[a]] += area * s * g[a][0];
        f[2 * tr[a] + 1] += area * s * g[a][1];
      }
    }
    for (int d = 0; d < 2 * n; ++d)
      if (fixed_dof(d)) f[d] = 0.0;
    const Eigen::VectorXd u = elastic.solve(f);
    r.A.push_back({u[2 * A], u[2 * A + 1]});
    r.B.push_back({u[2 * B], u[2 * B + 1]});
    r.C.push_back({u[2 * C], u[2 * C + 1]});
  }
  return r;
}

}  // namespace frostwall::test
