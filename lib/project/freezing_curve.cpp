// A smooth freezing curve's liquid share, onset and table bottom
// (project::FreezingCurve, project.hpp).
#include <algorithm>
#include <cmath>

#include "project/project.hpp"

namespace frostwall::project {

double FreezingCurve::liquid_fraction(double T, double Tf) const {
  if (T >= onset(Tf)) return 1.0;
  if (model == CurveModel::exponential) {
    const double x = (T - Tf) / width;
    return residual_saturation + (1.0 - residual_saturation) * std::exp(-x * x);
  }
  return std::min(1.0, alpha * std::pow(Tf - T, beta) / water_content);
}

double FreezingCurve::onset(double Tf) const {
  if (model == CurveModel::power) return Tf - std::pow(water_content / alpha, 1.0 / beta);
  return Tf;
}

double FreezingCurve::bottom(double Tf) const {
  if (model == CurveModel::exponential) return Tf - width * std::sqrt(std::log(1e6));
  return onset(Tf) - 60.0;
}

}  // namespace frostwall::project
