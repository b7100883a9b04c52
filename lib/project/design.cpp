#include "project/design.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

namespace frostwall::project {

std::string_view name(WallFormula f) {
  switch (f) {
    case WallFormula::lame_tresca: return "lame_tresca";
    case WallFormula::lame_mises: return "lame_mises";
    case WallFormula::domke: return "domke";
    case WallFormula::plastic_tresca: return "plastic_tresca";
    case WallFormula::plastic_mohr_coulomb: return "plastic_mohr_coulomb";
  }
  return "?";
}

StrengthLaw StrengthLaw::table(std::vector<std::pair<double, double>> points) {
  if (points.empty()) throw std::invalid_argument("StrengthLaw::table: no points");
  std::sort(points.begin(), points.end());
  StrengthLaw law;
  law.kind_ = Kind::table;
  law.points_ = std::move(points);
  return law;
}

StrengthLaw StrengthLaw::linear(double a, double b) {
  StrengthLaw law;
  law.kind_ = Kind::linear;
  law.p0_ = a, law.p1_ = b;
  return law;
}

StrengthLaw StrengthLaw::power(double sigma_0, double k, double m) {
  StrengthLaw law;
  law.kind_ = Kind::power;
  law.p0_ = sigma_0, law.p1_ = k, law.p2_ = m;
  return law;
}

double StrengthLaw::at(double T) const {
  const double cold = std::abs(std::min(T, 0.0));  // |T| below freezing; unfrozen ground: the 0 degC value
  switch (kind_) {
    case Kind::linear: return p0_ + p1_ * cold;
    case Kind::power: return p0_ + p1_ * std::pow(cold, p2_);
    case Kind::table: {
      if (T <= points_.front().first) return points_.front().second;
      if (T >= points_.back().first) return points_.back().second;
      const auto hi = std::upper_bound(points_.begin(), points_.end(), T,
                                       [](double t, const std::pair<double, double>& p) { return t < p.first; });
      const auto lo = hi - 1;
      const double w = (T - lo->first) / (hi->first - lo->first);
      return lo->second + w * (hi->second - lo->second);
    }
  }
  return 0.0;
}

std::string table_problem(const std::vector<std::pair<double, double>>& points) {
  if (points.size() < 2) return "needs at least two [T, sigma_c] points";
  auto sorted = points;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    if (sorted[k].second <= 0.0)
      return fmt::format("strength must be positive, got {} MPa at {} C", sorted[k].second, sorted[k].first);
    if (k > 0 && sorted[k].first == sorted[k - 1].first) return fmt::format("two strengths at {} C", sorted[k].first);
    if (k > 0 && sorted[k].second > sorted[k - 1].second)
      return fmt::format("strength must not fall as the soil gets colder: {} MPa at {} C, {} MPa at {} C",
                         sorted[k - 1].second, sorted[k - 1].first, sorted[k].second, sorted[k].first);
  }
  return {};
}

}  // namespace frostwall::project
