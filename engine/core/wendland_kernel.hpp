#pragma once
// Wendland C2 kernel shape (Wendland 1995) of support radius R, for the symmetric pressure
// gradient's pair force in 3D (`symmetric_kernel = "auto"`, the default, or "wendland";
// docs/method.md, the fifteenth session): with R = 2 d0 a lattice under pressure is stable in 2D
// and 3D, where the cubic spline's 3D lattice buckles (tests/unit/test_lattice_stability.cpp).
//   K(s) = (1 - s)^4 (1 + 4 s),  s = r / R < 1.
// Unnormalised: the operators that use it divide by its lattice sum (sph_context.cpp), as they
// do the cubic spline's.
namespace washout {

class WendlandShape {
 public:
  // A support of 0 marks the shape unused (SphContext then keeps the cubic spline).
  explicit WendlandShape(double support)
      : support_(support), inv_(support > 0.0 ? 1.0 / support : 0.0) {}

  double support() const { return support_; }

  // (dK/dr) / r = -20 (1 - s)^3 / R^2, finite at r -> 0.
  double derivative_over_r(double r) const {
    const double s = r * inv_;
    if (s >= 1.0) return 0.0;
    const double t = 1.0 - s;
    return -20.0 * t * t * t * inv_ * inv_;
  }

 private:
  double support_, inv_;
};

}  // namespace washout
