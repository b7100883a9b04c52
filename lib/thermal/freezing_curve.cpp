#include "thermal/freezing_curve.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::thermal {

using project::CurveModel;

double SmoothCurve::liquid_fraction(double T) const {
  if (T >= onset()) return 1.0;
  if (curve.model == CurveModel::exponential) {
    const double x = (T - freezing_point) / curve.width;
    return curve.residual_saturation + (1.0 - curve.residual_saturation) * std::exp(-x * x);
  }
  const double theta = freezing_point - T;
  return std::min(1.0, curve.alpha * std::pow(theta, curve.beta) / curve.water_content);
}

double SmoothCurve::onset() const {
  if (curve.model == CurveModel::power)
    return freezing_point - std::pow(curve.water_content / curve.alpha, 1.0 / curve.beta);
  return freezing_point;
}

double SmoothCurve::bottom() const {
  if (curve.model == CurveModel::exponential) return freezing_point - curve.width * std::sqrt(std::log(1e6));
  return onset() - 60.0;
}

}  // namespace frostwall::thermal
