#pragma once
// Cubic B-spline kernel (Monaghan 1985), compact support 2h, METHOD.md "SPH operators".
//   W(q) = sigma (1 - 1.5 q^2 + 0.75 q^3)   0 <= q < 1
//        = sigma 0.25 (2 - q)^3               1 <= q < 2,    q = r / h
//   sigma = 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D (2 / (3 h) in 1D: a wave gauge's
//   weights across the flow of a 2D scene, engine/sim/probes.cpp).
#include <numbers>

namespace washout {

class CubicSplineKernel {
 public:
  CubicSplineKernel(int dim, double h)
      : h_(h),
        inv_h_(1.0 / h),
        sigma_(dim == 1   ? 2.0 / (3.0 * h)
               : dim == 2 ? 10.0 / (7.0 * std::numbers::pi * h * h)
                          : 1.0 / (std::numbers::pi * h * h * h)) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }

  double value(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_ * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0) {
      const double s = 2.0 - q;
      return sigma_ * 0.25 * s * s * s;
    }
    return 0.0;
  }

  // dW/dr; grad_i W_ij = dW/dr(r_ij) * r_ij / |r_ij|.
  double derivative(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_ * inv_h_ * (-3.0 * q + 2.25 * q * q);
    if (q < 2.0) {
      const double s = 2.0 - q;
      return -sigma_ * inv_h_ * 0.75 * s * s;
    }
    return 0.0;
  }

  // (dW/dr) / r, finite at r -> 0: the factor that turns r_ij into grad W_ij.
  double derivative_over_r(double r) const {
    const double q = r * inv_h_;
    if (q < 1.0) return sigma_ * inv_h_ * inv_h_ * (-3.0 + 2.25 * q);
    if (q < 2.0) {
      const double s = 2.0 - q;
      return -sigma_ * inv_h_ * 0.75 * s * s / r;
    }
    return 0.0;
  }

 private:
  double h_, inv_h_, sigma_;
};

}  // namespace washout
