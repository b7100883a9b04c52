// A one-dimensional thaw with water flowing at one velocity through thawed
// and frozen ground, solved sharply as a reference for the particle runs:
//
//   C dT/dt + W dT/dx = k d2T/dx2     in each zone (W = rho_w c_w q),
//   T(0) = Ts, dT/dx(Lx) = 0, T = Tf at the front s(t),
//   Lv ds/dt = -k_u dT/dx(s-) + k_f dT/dx(s+).
//
// Front fixing (Landau): the thawed zone mapped to xi = x / s, the frozen
// zone to eta with x = s + (Lx - s) g(eta), g graded exponentially (cells
// 400 times finer at the front than at the far end, where the frozen zone's
// early profile is steep), each zone on its own fixed grid, central
// differences (second order), backward Euler with the front found by a
// secant iteration in every step, steps uniform in sqrt(t) (the front moves
// as sqrt(t) at first), and Richardson's extrapolation over two step sizes
// (second order in time). Starts at a tiny t0 from Neumann's
// similarity solution without flow (the water has carried heat a distance
// of order q t0 by then), which `neumann_lambda` also gives for checks.
#pragma once

#include <cmath>
#include <vector>

namespace frostwall::test {

struct ThawProblem {
  double k_thawed, C_thawed;  // W/(m K), J/(m3 K)
  double k_frozen, C_frozen;
  double latent;                     // J/m3
  double water;                      // rho_w c_w q, W/(m2 K), along +x
  double surface, melting, initial;  // degC: x = 0, the front, the ground at t = 0
  double length;                     // m, insulated far end
};

// Neumann's two-phase thaw without flow: s = 2 lambda sqrt(t).
inline double neumann_lambda(const ThawProblem& p) {
  const double au = p.k_thawed / p.C_thawed, af = p.k_frozen / p.C_frozen;
  auto g = [&](double l) {
    return p.k_thawed * (p.surface - p.melting) * std::exp(-l * l / au) /
               (std::sqrt(M_PI * au) * std::erf(l / std::sqrt(au))) -
           p.k_frozen * (p.melting - p.initial) * std::exp(-l * l / af) /
               (std::sqrt(M_PI * af) * std::erfc(l / std::sqrt(af))) -
           p.latent * l;
  };
  double a = 0.0, b = 1e-9;  // lambda is dimensional (m / sqrt(s)): bracket it by doubling
  while (g(b) > 0) a = b, b *= 2;
  for (int k = 0; k < 200; ++k) {
    const double c = 0.5 * (a + b);
    (g(a) * g(c) <= 0 ? b : a) = c;
  }
  return 0.5 * (a + b);
}

namespace detail {

// Thomas algorithm; a, b, c the sub-, main and super-diagonal.
inline void tridiagonal(std::vector<double> a, std::vector<double> b, const std::vector<double>& c,
                        std::vector<double>& d) {
  const std::size_t n = b.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double m = a[i] / b[i - 1];
    b[i] -= m * c[i - 1];
    d[i] -= m * d[i - 1];
  }
  d[n - 1] /= b[n - 1];
  for (std::size_t i = n - 1; i-- > 0;) d[i] = (d[i] - c[i] * d[i + 1]) / b[i];
}

// The frozen zone's grading: x = s + (Lx - s) g(eta), g(0) = 0, g(1) = 1.
constexpr double grading = 6.0;
inline double g(double eta) { return std::expm1(grading * eta) / std::expm1(grading); }
inline double g1(double eta) { return grading * std::exp(grading * eta) / std::expm1(grading); }
inline double g2(double eta) { return grading * g1(eta); }

// One zone's backward-Euler step on its mapped grid [0, 1] of n + 1 nodes:
// T(0) = left; at node n either T = right (held) or a zero gradient.
// drift(z) is the coefficient of dT/dz, diffusion(z) the one of d2T/dz2.
template <class Drift, class Diffusion>
void zone_step(std::vector<double>& T, const std::vector<double>& old, double C, double dt, Drift&& drift,
               Diffusion&& diffusion, double left, const double* right) {
  const std::size_t n = T.size() - 1;
  const double h = 1.0 / n;
  std::vector<double> a(n + 1, 0.0), b(n + 1, 1.0), c(n + 1, 0.0), d(n + 1, 0.0);
  d[0] = left;
  for (std::size_t i = 1; i < n; ++i) {
    const double v = drift(i * h), D = diffusion(i * h) / (h * h);
    a[i] = -v / (2 * h) - D;
    b[i] = C / dt + 2 * D;
    c[i] = v / (2 * h) - D;
    d[i] = C * old[i] / dt;
  }
  if (right) d[n] = *right;
  else {  // mirror node beyond the end: the same temperature as node n - 1
    a[n] = -2 * diffusion(1.0) / (h * h);
    b[n] = C / dt + 2 * diffusion(1.0) / (h * h);
    d[n] = C * old[n] / dt;
  }
  tridiagonal(a, b, c, d);
  T = d;
}

// The front s at each of `times` (increasing, s), with `nodes` per zone and
// `steps` backward-Euler steps per output interval.
inline std::vector<double> march(const ThawProblem& p, const std::vector<double>& times, int nodes, int steps) {
  const double lambda = neumann_lambda(p);
  const double au = p.k_thawed / p.C_thawed, af = p.k_frozen / p.C_frozen;
  double t = 1e-4 * times.front(), s = 2 * lambda * std::sqrt(t);
  std::vector<double> Tu(nodes + 1), Tf(nodes + 1);
  for (int i = 0; i <= nodes; ++i) {
    const double xu = s * i / nodes, xf = s + (p.length - s) * g(double(i) / nodes);
    Tu[i] = p.surface -
            (p.surface - p.melting) * std::erf(xu / (2 * std::sqrt(au * t))) / std::erf(lambda / std::sqrt(au));
    Tf[i] = p.initial +
            (p.melting - p.initial) * std::erfc(xf / (2 * std::sqrt(af * t))) / std::erfc(lambda / std::sqrt(af));
  }
  const double hu = 1.0 / nodes;
  std::vector<double> fronts;
  for (double target : times) {
    const double r0 = std::sqrt(t), dr = (std::sqrt(target) - r0) / steps;
    for (int n = 1; n <= steps; ++n) {
      const double t_new = n == steps ? target : (r0 + n * dr) * (r0 + n * dr), dt = t_new - t;
      const auto oldu = Tu, oldf = Tf;
      // The front's speed from the zones' gradients once both are stepped
      // with the front at s1; g(s1) = s1 - s - dt speed(s1) = 0.
      auto residual = [&](double s1) {
        const double ds = (s1 - s) / dt, l = p.length - s1;
        zone_step(
            Tu, oldu, p.C_thawed, dt, [&](double xi) { return (p.water - p.C_thawed * xi * ds) / s1; },
            [&](double) { return p.k_thawed / (s1 * s1); }, p.surface, &p.melting);
        // dT/dx = T_eta / (l g'), d2T/dx2 = (T_eta,eta - g'' / g' T_eta) / (l g')^2, and
        // dT/dt at fixed x = dT/dt at fixed eta - ds (1 - g) / (l g') T_eta.
        zone_step(
            Tf, oldf, p.C_frozen, dt,
            [&](double e) {
              return (p.water - p.C_frozen * ds * (1 - g(e))) / (l * g1(e)) +
                     p.k_frozen * g2(e) / (l * l * g1(e) * g1(e) * g1(e));
            },
            [&](double e) { return p.k_frozen / (l * l * g1(e) * g1(e)); }, p.melting, nullptr);
        const double gu = (3 * Tu[nodes] - 4 * Tu[nodes - 1] + Tu[nodes - 2]) / (2 * hu * s1);
        const double gf = (-3 * Tf[0] + 4 * Tf[1] - Tf[2]) / (2 * hu * l * g1(0.0));
        return s1 - s - dt * (-p.k_thawed * gu + p.k_frozen * gf) / p.latent;
      };
      double x0 = s, x1 = s * (1 + 1e-3) + 1e-9, f0 = residual(x0), f1 = residual(x1);
      for (int it = 0; it < 50 && f1 != 0.0 && f1 != f0; ++it) {
        const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        if (std::abs(x2 - x1) < 1e-13 * x1) break;
        x0 = x1, f0 = f1, x1 = x2, f1 = residual(x1);
      }
      s = x1, t = t_new;
    }
    fronts.push_back(s);
  }
  return fronts;
}

}  // namespace detail

// The front s at each of `times` (increasing, s): `nodes` per zone, `steps`
// and 2 `steps` per output interval, extrapolated.
inline std::vector<double> thaw_fronts(const ThawProblem& p, const std::vector<double>& times, int nodes, int steps) {
  const auto coarse = detail::march(p, times, nodes, steps), fine = detail::march(p, times, nodes, 2 * steps);
  std::vector<double> s(times.size());
  for (std::size_t k = 0; k < s.size(); ++k) s[k] = 2 * fine[k] - coarse[k];
  return s;
}

}  // namespace frostwall::test
