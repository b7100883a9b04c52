// Cell-linked list: points binned into square cells of the search radius,
// so a radius query looks at 3^Dim cells. Built once; particles never move.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "particles/vec.hpp"

namespace frostwall::particles {

template <int Dim>
class CellList {
 public:
  CellList(const std::vector<Vec<Dim>>& points, double radius) : points_(points), cell_(radius) {
    lo_ = Vec<Dim>::Constant(0.0);
    Vec<Dim> hi = lo_;
    if (!points.empty()) {
      lo_ = hi = points.front();
      for (const auto& p : points) {
        lo_ = lo_.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    }
    for (int d = 0; d < Dim; ++d) dims_[d] = 1 + static_cast<long>((hi[d] - lo_[d]) / cell_);
    long n_cells = 1;
    for (int d = 0; d < Dim; ++d) n_cells *= dims_[d];
    // Counting sort of point indices by cell.
    start_.assign(n_cells + 1, 0);
    std::vector<long> cell_of(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      cell_of[i] = linear(coords(points[i]));
      ++start_[cell_of[i] + 1];
    }
    for (long c = 0; c < n_cells; ++c) start_[c + 1] += start_[c];
    sorted_.resize(points.size());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i) sorted_[fill[cell_of[i]]++] = static_cast<std::uint32_t>(i);
  }

  // Calls visit(index, distance) for every point within `radius` of x.
  // Includes a point at x itself. A radius up to the cell size looks at
  // 3^Dim cells; a larger one (graded clouds, whose supports differ) at the
  // box of cells that covers it.
  template <class Visit>
  void for_each_within(const Vec<Dim>& x, double radius, Visit&& visit) const {
    std::array<long, Dim> lo, hi;
    if (!cell_box(x, radius, lo, hi)) return;
    const double r2 = radius * radius;
    visit_cells(lo, hi, 0, std::array<long, Dim>{}, [&](long cell) {
      for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const std::uint32_t j = sorted_[k];
        const double d2 = (points_[j] - x).squaredNorm();
        if (d2 < r2) visit(j, std::sqrt(d2));
      }
      return false;
    });
  }

  // Whether any point lies within `radius` of x: stops at the first.
  bool any_within(const Vec<Dim>& x, double radius) const {
    std::array<long, Dim> lo, hi;
    if (!cell_box(x, radius, lo, hi)) return false;
    const double r2 = radius * radius;
    return visit_cells(lo, hi, 0, std::array<long, Dim>{}, [&](long cell) {
      for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k)
        if ((points_[sorted_[k]] - x).squaredNorm() < r2) return true;
      return false;
    });
  }

 private:
  // The box of cells [lo, hi] that covers the ball (x, radius); false when
  // it misses the grid.
  bool cell_box(const Vec<Dim>& x, double radius, std::array<long, Dim>& lo, std::array<long, Dim>& hi) const {
    for (int d = 0; d < Dim; ++d) {
      lo[d] = std::max<long>(0, static_cast<long>(std::floor((x[d] - radius - lo_[d]) / cell_)));
      hi[d] = std::min<long>(dims_[d] - 1, static_cast<long>(std::floor((x[d] + radius - lo_[d]) / cell_)));
      if (lo[d] > hi[d]) return false;
    }
    return true;
  }
  std::array<long, Dim> coords(const Vec<Dim>& p) const {
    std::array<long, Dim> c;
    for (int d = 0; d < Dim; ++d) c[d] = std::clamp<long>(static_cast<long>((p[d] - lo_[d]) / cell_), 0, dims_[d] - 1);
    return c;
  }
  long linear(const std::array<long, Dim>& c) const {
    long index = 0;
    for (int d = Dim - 1; d >= 0; --d) index = index * dims_[d] + c[d];
    return index;
  }
  // Visits the cells of the box [lo, hi]; stops as soon as f returns true.
  template <class F>
  bool visit_cells(const std::array<long, Dim>& lo, const std::array<long, Dim>& hi, int d, std::array<long, Dim> c,
                   F&& f) const {
    if (d == Dim) return f(linear(c));
    for (c[d] = lo[d]; c[d] <= hi[d]; ++c[d])
      if (visit_cells(lo, hi, d + 1, c, f)) return true;
    return false;
  }

  const std::vector<Vec<Dim>>& points_;
  double cell_;
  Vec<Dim> lo_;
  std::array<long, Dim> dims_{};
  std::vector<std::uint32_t> start_;
  std::vector<std::uint32_t> sorted_;
};

}  // namespace frostwall::particles
