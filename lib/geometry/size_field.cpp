#include "geometry/size_field.hpp"

#include <algorithm>
#include <cmath>

namespace frostwall::geometry {

void SizeField::add(std::function<double(const Vec2&)> distance, double spacing, double slope) {
  sources_.push_back({std::move(distance), spacing, slope});
}

void SizeField::near_circle(const Vec2& centre, double radius, double spacing, double slope) {
  add([=](const Vec2& x) { return std::max(0.0, (x - centre).norm() - radius); }, spacing, slope);
}

void SizeField::in_annulus(double r_in, double r_out, double spacing, double slope) {
  add(
      [=](const Vec2& x) {
        const double r = x.norm();
        return std::max({0.0, r_in - r, r - r_out});
      },
      spacing, slope);
}

void SizeField::near_line(const Vec2& point, const Vec2& normal, double width, double spacing, double slope) {
  add([=](const Vec2& x) { return std::max(0.0, std::abs((x - point).dot(normal)) - width); }, spacing, slope);
}

double SizeField::operator()(const Vec2& x) const {
  double s = coarsest_;
  for (const auto& source : sources_) s = std::min(s, source.spacing + source.slope * source.distance(x));
  return std::max(s, finest_);
}

}  // namespace frostwall::geometry
