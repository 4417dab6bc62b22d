// Optional sub-particle-scale turbulence (METHOD.md "Fluid": tau, Smagorinsky type):
//   nu_t = (C_s d0)^2 |S|,  |S| = sqrt(2 S:S),  S = (grad u + grad u^T) / 2,
// with the velocity gradient from the difference form <grad f>_i = sum_j V (f_j - f_i) grad W_ij.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void compute_eddy_viscosity(const SphContext& ctx, const NeighborList& list, const Particles& p,
                            double smagorinsky_constant, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  work.eddy_viscosity.assign(n, 0.0);
  const double length2 = std::pow(smagorinsky_constant * ctx.d0, 2);
  with_dimension(ctx.dim, [&](auto dim) {
    constexpr int D = dim;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double grad[D][D] = {};  // grad[a][b] = d u_a / d x_b
      double u_i[D];
      for (int a = 0; a < D; ++a) u_i[a] = p.velocity[a][i];
      for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
        const double f = ctx.gradient_weight(q.r);
        for (int a = 0; a < D; ++a) {
          const double uj = q.j < n ? p.velocity[a][q.j] : work.boundary.marker_velocity[a][q.j];
          const double du = uj - u_i[a];
          for (int b = 0; b < D; ++b) grad[a][b] += du * f * q.d[b];
        }
      });
      double ss = 0.0;
      for (int a = 0; a < D; ++a)
        for (int b = 0; b < D; ++b) {
          const double s = 0.5 * (grad[a][b] + grad[b][a]);
          ss += s * s;
        }
      work.eddy_viscosity[i] = length2 * std::sqrt(2.0 * ss);
    }
  });
}

}  // namespace washout
