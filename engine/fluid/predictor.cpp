// Step 1 of METHOD.md, the predictor: u*_i = u_i + dt (nu <lap u>_i + (1/rho0) <div tau>_i + g).
// The laplacian is METHOD.md's
//   <lap f>_i = sum_j V_j 2 (r_ij . grad W_ij) / (|r_ij|^2 + eta^2) (f_i - f_j),
// normalised on the lattice. Boundary neighbours contribute their virtual-marker velocity, which
// carries the slip condition. The sub-particle-scale stress enters as an eddy viscosity:
// (1/rho0) div tau = div (2 nu_t S) ~ nu_t,ij <lap u> with nu_t,ij the pair average.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void predict_velocity(const SphContext& ctx, const NeighborList& list, const Particles& p,
                      double viscosity, const Vec3& gravity, double dt, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  for (int a = 0; a < 3; ++a) work.u_star[a].resize(n);
  const bool turbulent = !work.eddy_viscosity.empty();
  with_dimension(ctx.dim, [&](auto dim) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double lap[3] = {0, 0, 0};
      double u_i[3] = {0, 0, 0};
      for (int a = 0; a < dim; ++a) u_i[a] = p.velocity[a][i];
      const double nu_t_i = turbulent ? work.eddy_viscosity[i] : 0.0;
      for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
        const bool fluid = q.j < n;
        double weight = ctx.laplacian_weight(q.r, q.r2);
        if (turbulent)
          weight *= viscosity + 0.5 * (nu_t_i + (fluid ? work.eddy_viscosity[q.j] : nu_t_i));
        else
          weight *= viscosity;
        for (int a = 0; a < dim; ++a) {
          const double uj = fluid ? p.velocity[a][q.j] : work.boundary.marker_velocity[a][q.j];
          lap[a] += weight * (u_i[a] - uj);
        }
      });
      for (int a = 0; a < 3; ++a)
        work.u_star[a][i] = a < dim ? u_i[a] + dt * (lap[a] + gravity[a]) : 0.0;
    }
  });
}

}  // namespace washout
