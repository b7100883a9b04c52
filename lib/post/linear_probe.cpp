#include "post/linear_probe.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace frostwall::post {

LinearProbe::LinearProbe(const std::vector<particles::Vec<2>>& points, const std::vector<particles::Vec<2>>& where,
                         double radius) {
  start_.push_back(0);
  for (const auto& x0 : where) {
    double R = radius;
    std::vector<std::uint32_t> near;
    for (int grow = 0; grow < 40; ++grow, R *= 1.5) {
      near.clear();
      for (std::uint32_t k = 0; k < points.size(); ++k)
        if ((points[k] - x0).norm() < R) near.push_back(k);
      if (near.size() >= 6) break;
    }
    // Weighted least squares for f = a + b . (x - x0); the value at x0 is a.
    Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
    std::vector<Eigen::Vector3d> p(near.size());
    std::vector<double> w(near.size());
    for (std::size_t m = 0; m < near.size(); ++m) {
      const particles::Vec<2> d = points[near[m]] - x0;
      const double q = 1.0 - d.norm() / R;
      w[m] = q * q;
      p[m] = Eigen::Vector3d(1.0, d[0], d[1]);
      M += w[m] * p[m] * p[m].transpose();
    }
    const Eigen::Vector3d first = M.ldlt().solve(Eigen::Vector3d(1.0, 0.0, 0.0));  // M is symmetric
    for (std::size_t m = 0; m < near.size(); ++m) {
      index_.push_back(near[m]);
      weight_.push_back(w[m] * first.dot(p[m]));
    }
    start_.push_back(index_.size());
  }
}

double LinearProbe::at(std::size_t k, const std::vector<double>& field) const { return at(k, field, 1, 0); }

double LinearProbe::at(std::size_t k, const std::vector<double>& field, int stride, int c) const {
  double v = 0.0;
  for (std::size_t e = start_[k]; e < start_[k + 1]; ++e) v += weight_[e] * field[index_[e] * stride + c];
  return v;
}

}  // namespace frostwall::post
