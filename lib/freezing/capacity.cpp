#include "freezing/capacity.hpp"
#include "freezing/model.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/core.h>
#include <string>
#include <unistd.h>
#include <vector>

#include "geometry/layout.hpp"
#include "geometry/rectangle.hpp"
#include "geometry/shaft_section.hpp"
#include "geometry/symmetry.hpp"

namespace frostwall::freezing {

namespace {

// Particles per unit area where the size field asks for spacing s: the
// graded placement gives each particle an area s^2, as the lattice does
// (measured: within 1 % on the shipped clouds, tests/test_capacity.cpp).
double density(double s) { return 1.0 / (s * s); }

// Free particles of a graded wedge: the density integrated by the midpoint
// rule on a polar grid. The radial grid is refined between breakpoints (the
// wall band and the cones around it), so a band of a few metres is seen
// even when the domain is a million metres across.
double graded_wedge_particles(const geometry::SizeField& size, const geometry::Wedge& wedge, double R,
                              std::vector<double> breaks) {
  breaks.push_back(0.0);
  breaks.push_back(R);
  for (auto& b : breaks) b = std::clamp(b, 0.0, R);
  std::sort(breaks.begin(), breaks.end());
  const int per_interval = 48, angles = 96;
  double count = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    if (!(b > a)) continue;
    const double dr = (b - a) / per_interval, dtheta = wedge.angle / angles;
    for (int i = 0; i < per_interval; ++i) {
      const double r = a + (i + 0.5) * dr;
      for (int j = 0; j < angles; ++j) {
        const double theta = wedge.start_angle + (j + 0.5) * dtheta;
        count += density(size(particles::Vec<2>(r * std::cos(theta), r * std::sin(theta)))) * r * dr * dtheta;
      }
    }
  }
  return count;
}

double shaft_particles(const project::Project& p, double spacing, double R) {
  auto section = std::get<project::ShaftSection>(p.geometry);
  section.outer_radius = R;
  const auto wedge = geometry::symmetry_wedge(section);
  const double copies = p.numerics.use_symmetry ? 1.0 : 2.0 * M_PI / wedge.angle;
  if (p.numerics.placement == project::Placement::lattice)
    return copies * 0.5 * wedge.angle * R * R / (spacing * spacing);
  const auto& g = p.numerics.grading;
  const auto size = geometry::shaft_size_field(section, wedge, spacing, g);
  double r_in = R, r_out = 0.0;
  for (const auto& q : geometry::pipe_positions(section.layout)) {
    r_in = std::min(r_in, std::hypot(q.x, q.y));
    r_out = std::max(r_out, std::hypot(q.x, q.y));
  }
  const double w = g.band_width.value_or(2.0), cone = (g.coarsening - 1.0) * spacing / (g.growth - 1.0);
  return copies *
         graded_wedge_particles(size, wedge, R, {r_in - w - cone, r_in - w, r_in, r_out, r_out + w, r_out + w + cone});
}

double rectangle_particles(const project::Project& p, const project::Rectangle& rect, double spacing) {
  if (p.numerics.placement == project::Placement::lattice) return rect.width * rect.height / (spacing * spacing);
  const auto size = geometry::rectangle_size_field(rect, spacing, p.numerics.grading);
  const int n = 256;
  double count = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      count += density(size(particles::Vec<2>((i + 0.5) * rect.width / n, (j + 0.5) * rect.height / n)));
  return count * rect.width * rect.height / (n * n);
}

double particles(const project::Project& p, double spacing, double R) {
  if (const auto* rect = std::get_if<project::Rectangle>(&p.geometry)) return rectangle_particles(p, *rect, spacing);
  return shaft_particles(p, spacing, R);
}

// x rounded up (down) to two significant digits: a value to type in.
double round_up(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::ceil(x / unit * (1.0 - 1e-12)) * unit;
}
double round_down(double x) {
  const double unit = std::pow(10.0, std::floor(std::log10(x)) - 1.0);
  return std::floor(x / unit * (1.0 + 1e-12)) * unit;
}

// A length as a user writes it: 0.000001, 1000000, 0.0022.
std::string plain(double x) {
  std::string text = fmt::format("{:.12f}", x);
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

// 3.1e11, as an engineer writes it (no "+", no leading zero).
std::string sci(double x) {
  const int exponent = static_cast<int>(std::floor(std::log10(x)));
  double mantissa = x / std::pow(10.0, exponent);
  if (std::round(mantissa * 10.0) >= 100.0) return fmt::format("1.0e{}", exponent + 1);
  return fmt::format("{:.1f}e{}", mantissa, exponent);
}

}  // namespace

double default_particle_limit() {
  const double memory = static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  return memory > 0.0 ? 0.5 * memory / bytes_per_particle : 1e6;
}

CapacityEstimate estimate_capacity(const project::Project& p, double spacing) {
  CapacityEstimate e;
  e.limit = p.numerics.max_particles ? static_cast<double>(*p.numerics.max_particles) : default_particle_limit();
  const double R = std::holds_alternative<project::ShaftSection>(p.geometry)
                       ? std::get<project::ShaftSection>(p.geometry).outer_radius
                       : 0.0;
  e.particles = particles(p, spacing, R);
  return e;
}

void check_capacity(const project::Project& p, double spacing) {
  if (const auto* section = std::get_if<project::ShaftSection>(&p.geometry)) {
    if (const auto problems = geometry::layout_problems(*section); !problems.empty())
      throw project::ProjectError(problems);
    // Line sinks: the gap between two pipe walls holds a few particles.
    const double gap = narrowest_gap(*section);
    if (section->pipe.model == project::PipeModel::line && spacing > gap / min_rows_in_gap * (1 + 1e-9))
      throw project::ProjectError({fmt::format(
          "numerics.spacing: {} m leaves fewer than {} particles across the narrowest gap between two pipe walls "
          "({} m); use {} m or less",
          plain(spacing), min_rows_in_gap, plain(gap), plain(round_down(gap / min_rows_in_gap)))});
  }
  const CapacityEstimate e = estimate_capacity(p, spacing);
  if (e.fits()) return;
  const std::string needs = fmt::format("needs about {} particles (limit {}", sci(e.particles), sci(e.limit));
  const std::string source = p.numerics.max_particles ? ", numerics.max_particles)" : ", from this machine's memory)";
  // The count goes as 1 / spacing^2: the spacing that fits, rounded up.
  const double fitting_spacing = round_up(spacing * std::sqrt(e.particles / e.limit) * 1.05);
  if (const auto* section = std::get_if<project::ShaftSection>(&p.geometry)) {
    // Blame the outer radius when the same spacing fits in a domain three
    // times the pipe rings' radius (the usual far field), else the spacing.
    double r_out = 0.0;
    for (const auto& q : geometry::pipe_positions(section->layout)) r_out = std::max(r_out, std::hypot(q.x, q.y));
    const double usual = std::min(section->outer_radius, 3.0 * r_out);
    if (particles(p, spacing, usual) <= e.limit) {
      double lo = usual, hi = section->outer_radius;  // fits at lo, not at hi
      for (int k = 0; k < 40 && hi > 1.01 * lo; ++k) {
        const double mid = std::sqrt(lo * hi);
        (particles(p, spacing, mid) <= e.limit ? lo : hi) = mid;
      }
      throw project::ProjectError({fmt::format("domain.outer_radius: {} m {}{}; use an outer radius of {} m or less",
                                               plain(section->outer_radius), needs, source, plain(round_down(lo)))});
    }
  }
  throw project::ProjectError({fmt::format("numerics.spacing: {} m {}{}; use a spacing of {} m or more", plain(spacing),
                                           needs, source, plain(fitting_spacing))});
}

}  // namespace frostwall::freezing
