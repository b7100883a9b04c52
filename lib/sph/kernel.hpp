// Smoothing kernels W(r, h) with compact support 2h, normalised in Dim
// dimensions. Only dW/dr enters the conduction operator.
#pragma once

#include <memory>
#include <numbers>
#include <string>

#include "project/numerics.hpp"

namespace frostwall::sph {

class Kernel {
 public:
  virtual ~Kernel() = default;
  virtual double value(double r, double h) const = 0;
  virtual double derivative(double r, double h) const = 0;  // dW/dr
  virtual std::string name() const = 0;
  static constexpr double support_factor = 2.0;  // W = 0 for r >= 2h
};

// Wendland C2: W = a (1 - q/2)^4 (2q + 1), q = r/h. Positive Fourier
// transform, so no pairing instability; the default.
template <int Dim>
class WendlandC2 final : public Kernel {
 public:
  static constexpr double norm() {
    if constexpr (Dim == 2) return 7.0 / (4.0 * std::numbers::pi);
    else return 21.0 / (16.0 * std::numbers::pi);
  }
  double value(double r, double h) const override {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double a = 1.0 - 0.5 * q;
    return norm() / pow_h(h) * a * a * a * a * (2.0 * q + 1.0);
  }
  double derivative(double r, double h) const override {
    const double q = r / h;
    if (q >= 2.0) return 0.0;
    const double a = 1.0 - 0.5 * q;
    return -5.0 * norm() / (pow_h(h) * h) * q * a * a * a;
  }
  std::string name() const override { return "wendland_c2"; }

 private:
  static double pow_h(double h) { return Dim == 2 ? h * h : h * h * h; }
};

// Cubic B-spline (Monaghan & Lattanzio 1985), support 2h.
template <int Dim>
class CubicSpline final : public Kernel {
 public:
  static constexpr double norm() {
    if constexpr (Dim == 2) return 10.0 / (7.0 * std::numbers::pi);
    else return 1.0 / std::numbers::pi;
  }
  double value(double r, double h) const override {
    const double q = r / h;
    const double s = norm() / pow_h(h);
    if (q < 1.0) return s * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) return s * 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return 0.0;
  }
  double derivative(double r, double h) const override {
    const double q = r / h;
    const double s = norm() / (pow_h(h) * h);
    if (q < 1.0) return s * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) return -s * 0.75 * (2.0 - q) * (2.0 - q);
    return 0.0;
  }
  std::string name() const override { return "cubic_spline"; }

 private:
  static double pow_h(double h) { return Dim == 2 ? h * h : h * h * h; }
};

template <int Dim>
std::unique_ptr<Kernel> make_kernel(project::KernelKind kind) {
  switch (kind) {
    case project::KernelKind::cubic_spline: return std::make_unique<CubicSpline<Dim>>();
    case project::KernelKind::wendland_c2: break;
  }
  return std::make_unique<WendlandC2<Dim>>();
}

}  // namespace frostwall::sph
