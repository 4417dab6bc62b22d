// Step 1 of METHOD.md, the predictor: u*_i = u_i + dt (nu <lap u>_i + (1/rho0) <div tau>_i + g).
// The laplacian is METHOD.md's
//   <lap f>_i = sum_j V_j 2 (r_ij . grad W_ij) / (|r_ij|^2 + eta^2) (f_i - f_j),
// normalised on the lattice. Boundary neighbours contribute their virtual-marker velocity, which
// carries the slip condition. The sub-particle-scale stress enters as an eddy viscosity:
// (1/rho0) div tau = div (2 nu_t S) ~ nu_t,ij <lap u> with nu_t,ij the pair average; a wall
// pair takes nu_t,i, or nothing where the law of the wall is to carry the wall's turbulent stress
// alone (turbulence_at_walls = "wall_function"). At a no-slip wall the markers' mirrored velocity
// gives the first layer a shear of order u_t / d0, so nu_t,i = (C_s d0)^2 |S| times that shear is
// a wall stress c C_s^2 u_t^2 whatever the spacing (c = 1.7 on the lattice,
// tests/unit/test_turbulence_at_walls.cpp): 7 to 12 times the law of the wall's u_*^2 for y+ from
// 100 to 1000 (docs/method.md, the thirty-third session).
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void predict_velocity(const SphContext& ctx, const NeighborList& list, const Particles& p,
                      double viscosity, const Vec3& gravity, double dt, FluidWork& work,
                      bool eddy_viscosity_at_walls) {
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
      const double nu_t_wall = eddy_viscosity_at_walls ? nu_t_i : 0.0;  // a wall pair's
      for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
        const bool fluid = q.j < n;
        double weight = ctx.laplacian_weight(q.r, q.r2);
        if (turbulent)
          weight *= viscosity + (fluid ? 0.5 * (nu_t_i + work.eddy_viscosity[q.j]) : nu_t_wall);
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
