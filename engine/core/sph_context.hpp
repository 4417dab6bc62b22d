#pragma once
// What every SPH stage needs to know and that is fixed for a run: the kernel, particle mass
// and volume, and the lattice normalisation of the operators.
#include <cmath>

#include "engine/core/cubic_spline_kernel.hpp"
#include "engine/core/particles.hpp"
#include "engine/core/periodic_box.hpp"
#include "engine/core/wendland_kernel.hpp"

namespace washout {

struct SphContext {
  int dim = 2;
  double d0 = 0.0, h = 0.0;
  double rho0 = 1000.0;
  double volume = 0.0;  // V = d0^dim, equal for all particles (keeps the PPE symmetric)
  double mass = 0.0;    // m = rho0 V
  double eta2 = 0.0;    // eta^2 = 1e-4 h^2 in the laplacian's denominator
  CubicSplineKernel kernel{2, 1.0};
  PeriodicBox periodic;
  // Kernel sums over a perfect lattice with full support. Dividing by them makes the operators
  // exact on the initial lattice: the summation density of an interior particle equals rho0, the
  // gradient of a linear field and the laplacian of a quadratic field are exact there.
  double full_support_density = 0.0;  // sum_j m W_ij including j = i
  int full_support_neighbours = 0;    // lattice points within 2h, i excluded (20 in 2D, 56 in 3D)
  double gradient_correction = 1.0;
  double laplacian_correction = 1.0;
  // The symmetric pressure gradient's pair force: the cubic spline (symmetric_shape support 0)
  // or a Wendland C2 shape of support 2 d0, with its own lattice normalisation.
  WendlandShape symmetric_shape{0.0};
  double symmetric_correction = 1.0;

  SphContext(int dim, double d0, double h_over_d0, double rho0, const PeriodicBox& periodic);

  // Makes the symmetric gradient's pair force the Wendland C2 shape of support 2 d0.
  void use_wendland_symmetric_gradient();

  // x_i - x_j with the periodic minimum image.
  void displacement(const Particles& p, std::size_t i, std::size_t j, double d[3]) const {
    d[0] = p.position[0][i] - p.position[0][j];
    d[1] = p.position[1][i] - p.position[1][j];
    d[2] = p.position[2][i] - p.position[2][j];
    if (periodic.any()) periodic.minimum_image(d);
  }

  // V grad W_ij = gradient_weight(r) r_ij, with the lattice normalisation: the pair factor of
  // every gradient and divergence (sph_operators.hpp).
  double gradient_weight(double r) const {
    return gradient_correction * volume * kernel.derivative_over_r(r);
  }

  // V grad K_ij = symmetric_gradient_weight(r) r_ij for the symmetric pressure gradient (and its
  // own term in the PPE's diagonal); the cubic spline's gradient_weight unless
  // use_wendland_symmetric_gradient() was called.
  double symmetric_gradient_weight(double r) const {
    if (symmetric_has_own_kernel())
      return symmetric_correction * volume * symmetric_shape.derivative_over_r(r);
    return gradient_weight(r);
  }
  bool symmetric_has_own_kernel() const { return symmetric_shape.support() > 0.0; }

  // The laplacian's pair weight 2 V (r . grad W) / (r^2 + eta^2) (METHOD.md, with r . grad W =
  // W'(r) r and the lattice normalisation); <lap f>_i = sum_j laplacian_weight (f_i - f_j).
  double laplacian_weight(double r, double r2) const {
    return 2.0 * laplacian_correction * volume * kernel.derivative(r) * r / (r2 + eta2);
  }
};

}  // namespace washout
