#include "post/closure.hpp"

#include "sph/cell_list.hpp"

namespace frostwall::post {

ClosureDetector::ClosureDetector(const std::vector<sph::Vec<2>>& position, std::size_t n_free, double spacing,
                                 double far_field_radius) {
  const std::vector<sph::Vec<2>> free(position.begin(), position.begin() + n_free);
  const double link = 1.5 * spacing;
  const sph::CellList<2> cells(free, link);
  start_.assign(n_free + 1, 0);
  for (std::size_t i = 0; i < n_free; ++i) {
    cells.for_each_within(free[i], link, [&](std::uint32_t j, double) {
      if (j != i) link_.push_back(j);
    });
    start_[i + 1] = link_.size();
    if (free[i].norm() > far_field_radius - link) far_field_.push_back(static_cast<std::uint32_t>(i));
    if (free[i].norm() < free[axis_].norm()) axis_ = static_cast<std::uint32_t>(i);
  }
}

bool ClosureDetector::closed(const std::vector<double>& f) const {
  if (f[axis_] <= 0.5) return true;  // the ground at the axis itself froze
  std::vector<char> reached(start_.size() - 1, 0);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t s : far_field_)
    if (f[s] > 0.5) {
      reached[s] = 1;
      stack.push_back(s);
    }
  while (!stack.empty()) {
    const std::uint32_t i = stack.back();
    stack.pop_back();
    if (i == axis_) return false;
    for (std::size_t e = start_[i]; e < start_[i + 1]; ++e) {
      const std::uint32_t j = link_[e];
      if (!reached[j] && f[j] > 0.5) {
        reached[j] = 1;
        stack.push_back(j);
      }
    }
  }
  return true;
}

}  // namespace frostwall::post
