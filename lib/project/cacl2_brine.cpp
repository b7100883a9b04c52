#include "project/cacl2_brine.hpp"

#include "project/plant.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace frostwall::project {

namespace {

// Melinder's coefficients by term (i, j), i = 0..5 and j = 0..min(3, 5 - i)
// in that order (00 01 02 03 10 11 ... 41 50); columns: freezing point
// (degC), density (kg/m3), heat capacity (J/(kg K)), conductivity
// (W/(m K)), ln(viscosity / mPa s).
constexpr int terms = 18;
constexpr std::array<std::array<double, 5>, terms> melinder{{
    {-16.21, 1171, 3133, 0.558, 0.8939},
    {-0.0001344, -0.1463, 2.81, 0.00146, -0.02647},
    {0.000005073, -0.001302, -0.01563, 0.0000003861, 0.0001718},
    {-0.0000000482, -0.0001871, -0.00001233, 0.00000001307, -0.0000007918},
    {-1.555, 9.847, -44.8, -0.00115, 0.04389},
    {0.00002146, -0.02488, 0.03271, -0.00001008, 0.0002102},
    {-0.0000015, -0.000553, -0.001205, -0.0000000654, -0.0000008688},
    {0.00000002219, 0.00001665, 0.000009346, 0.0000000004728, -0.00000004353},
    {-0.05496, 0.03389, 0.9511, -0.00001784, 0.0009121},
    {0.0000009415, -0.002302, -0.005191, 0.0000003496, 0.000003993},
    {0.00000006185, 0.00003526, 0.0002282, -0.00000000484, 0.0000003785},
    {-0.000000001723, 0.0000002788, -0.000000929, -0.0000000002011, -0.000000009979},
    {-0.002624, 0.001062, 0.01472, -0.0000004415, 0.000001963},
    {-0.0000001082, 0.00006291, 0.0001615, -0.000000003462, -0.0000004892},
    {0.000000003036, 0.000001806, 0.000005073, 0.0000000003922, 0.00000000001526},
    {-0.0001726, 0.00002785, -0.001346, 0.00000004699, 0.0000002997},
    {-0.000000004396, 0.000006423, -0.000009754, 0.0000000006179, -0.00000003631},
    {-0.000004494, -0.000001811, -0.00006674, 0.000000002929, 0.00000003435},
}};
constexpr double xm = 18.7414, tm = 7.5257;

// Column c of the fit at x (mass %) and t (degC); the freezing point takes
// the terms in x alone.
double fit(int c, double x, double t, bool x_only = false) {
  double f = 0.0;
  int k = 0;
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j <= std::min(3, 5 - i); ++j, ++k)
      if (!x_only || j == 0) f += melinder[k][c] * std::pow(x - xm, i) * std::pow(t - tm, j);
  return f;
}

}  // namespace

BrineProperties cacl2_brine(double mass_fraction, double T) {
  const double x = 100.0 * mass_fraction;
  return {fit(1, x, T), 1e-3 * std::exp(fit(4, x, T)), fit(3, x, T), fit(2, x, T)};
}

double cacl2_freezing_point(double mass_fraction) { return fit(0, 100.0 * mass_fraction, 0.0, true); }

BrineProperties BrineOverrides::at(double T) const {
  const auto b = cacl2_brine(mass_fraction, T);
  return {density.value_or(b.density), viscosity.value_or(b.viscosity), conductivity.value_or(b.conductivity),
          heat_capacity.value_or(b.heat_capacity)};
}

double BrineOverrides::freezing_point() const { return cacl2_freezing_point(mass_fraction); }

}  // namespace frostwall::project
