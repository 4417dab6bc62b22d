#include "engine/core/sph_context.hpp"

namespace washout {
namespace {

// Calls visit(r) with the distance from the origin to every point of a perfect lattice of spacing
// d0 closer than radius, the origin excluded, in a fixed order.
template <class Visit>
void for_each_lattice_distance(int dim, double d0, double radius, Visit&& visit) {
  const int reach = static_cast<int>(std::ceil(radius / d0)) + 1;
  for (int k = (dim == 3 ? -reach : 0); k <= (dim == 3 ? reach : 0); ++k)
    for (int j = -reach; j <= reach; ++j)
      for (int i = -reach; i <= reach; ++i) {
        if (i == 0 && j == 0 && k == 0) continue;
        const double r = d0 * std::sqrt(double(i * i + j * j + k * k));
        if (r < radius) visit(r);
      }
}

}  // namespace

SphContext::SphContext(int dim_, double d0_, double h_over_d0, double rho0_,
                       const PeriodicBox& periodic_)
    : dim(dim_),
      d0(d0_),
      h(h_over_d0 * d0_),
      rho0(rho0_),
      volume(std::pow(d0_, dim_)),
      mass(rho0_ * std::pow(d0_, dim_)),
      eta2(1e-4 * h * h),
      kernel(dim_, h_over_d0 * d0_),
      periodic(periodic_) {
  double density = mass * kernel.value(0.0), gradient_sum = 0.0, laplacian_sum = 0.0;
  for_each_lattice_distance(dim, d0, 2.0 * h, [&](double r) {
    ++full_support_neighbours;
    density += mass * kernel.value(r);
    const double minus_r_dot_grad = -kernel.derivative(r) * r;  // -(r . grad W) >= 0
    gradient_sum += volume * minus_r_dot_grad;
    laplacian_sum += volume * minus_r_dot_grad * r * r / (r * r + eta2);
  });
  full_support_density = density;
  gradient_correction = dim / gradient_sum;
  laplacian_correction = dim / laplacian_sum;
}

void SphContext::use_wendland_symmetric_gradient() {
  symmetric_shape = WendlandShape(2.0 * d0);
  // The lattice normalisation, as for the cubic spline: sum_j V (-r . grad K) = dim.
  double sum = 0.0;
  for_each_lattice_distance(dim, d0, symmetric_shape.support(), [&](double r) {
    sum -= volume * symmetric_shape.derivative_over_r(r) * r * r;
  });
  symmetric_correction = dim / sum;
}

}  // namespace washout
