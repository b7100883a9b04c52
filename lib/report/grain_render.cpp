#include "report/grain_render.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace frostwall::report {

namespace {

using V3 = std::array<double, 3>;

double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
V3 unit(const V3& a) {
  const double n = std::sqrt(dot(a, a));
  return {a[0] / n, a[1] / n, a[2] / n};
}

// The camera's frame: `right` and `up` span the picture, `toward` points
// from the scene to the camera.
struct Camera {
  V3 right, up, toward;
};

Camera camera_of(const GrainView& v) {
  const int a1 = (v.up_axis + 1) % 3, a2 = (v.up_axis + 2) % 3;
  const double az = v.azimuth_deg * std::numbers::pi / 180.0, el = v.elevation_deg * std::numbers::pi / 180.0;
  V3 vertical{}, toward{};
  vertical[v.up_axis] = 1.0;
  toward[a1] = std::cos(el) * std::cos(az);
  toward[a2] = std::cos(el) * std::sin(az);
  toward[v.up_axis] = std::sin(el);
  const V3 right = unit(cross(vertical, toward));
  return {right, cross(toward, right), toward};
}

}  // namespace

RgbaImage render_grains(const std::vector<V3>& centre, const std::vector<double>& diameter,
                        const std::vector<std::array<std::uint8_t, 3>>& colour, const V3& low, const V3& high,
                        const GrainView& view) {
  if (diameter.size() != centre.size() || colour.size() != centre.size())
    throw std::invalid_argument("render_grains: centres, diameters and colours differ in number");
  if (view.up_axis < 0 || view.up_axis > 2 || std::abs(view.elevation_deg) >= 90.0)
    throw std::invalid_argument("render_grains: the vertical must be an axis and the camera off the vertical");
  const Camera cam = camera_of(view);
  // Fit the box's projected corners into the picture with a margin.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (int k = 0; k < 8; ++k) {
    const V3 p{k & 1 ? high[0] : low[0], k & 2 ? high[1] : low[1], k & 4 ? high[2] : low[2]};
    x0 = std::min(x0, dot(p, cam.right)), x1 = std::max(x1, dot(p, cam.right));
    y0 = std::min(y0, dot(p, cam.up)), y1 = std::max(y1, dot(p, cam.up));
  }
  const double margin = 8.0;
  const double scale = std::min((view.width - 2 * margin) / (x1 - x0), (view.height - 2 * margin) / (y1 - y0));
  const double ox = 0.5 * (view.width - scale * (x1 - x0)), oy = 0.5 * (view.height - scale * (y1 - y0));

  RgbaImage image(view.width, view.height);
  std::vector<double> depth(std::size_t(view.width) * std::size_t(view.height),
                            std::numeric_limits<double>::infinity());
  const V3 light = unit({-0.45, 0.6, 0.66});  // upper left, toward the viewer (camera frame)
  for (std::size_t i = 0; i < centre.size(); ++i) {
    const V3& p = centre[i];
    if (view.cut_axis >= 0 && p[view.cut_axis] < view.cut_at) continue;
    const double r = 0.5 * diameter[i] * scale;  // pixels
    const double cx = ox + (dot(p, cam.right) - x0) * scale, cy = oy + (y1 - dot(p, cam.up)) * scale;
    const double cz = -dot(p, cam.toward) * scale;  // larger is farther
    const int xa = std::max(0, int(std::floor(cx - r))), xb = std::min(view.width - 1, int(std::ceil(cx + r)));
    const int ya = std::max(0, int(std::floor(cy - r))), yb = std::min(view.height - 1, int(std::ceil(cy + r)));
    for (int y = ya; y <= yb; ++y)
      for (int x = xa; x <= xb; ++x) {
        const double dx = (x + 0.5 - cx) / r, dy = (cy - (y + 0.5)) / r, q = dx * dx + dy * dy;
        if (q >= 1.0) continue;
        const double dz = std::sqrt(1.0 - q);
        double& z = depth[std::size_t(y) * std::size_t(view.width) + std::size_t(x)];
        if (cz - dz * r >= z) continue;
        z = cz - dz * r;
        const double shade = 0.35 + 0.65 * std::max(0.0, dx * light[0] + dy * light[1] + dz * light[2]);
        std::uint8_t* px = image.at(x, y);
        for (int c = 0; c < 3; ++c) px[c] = std::uint8_t(std::lround(shade * colour[i][c]));
        px[3] = 255;
      }
  }
  return image;
}

}  // namespace frostwall::report
