// The source of the stabilized PPE (METHOD.md step 2, Asai et al. 2012):
//   b_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2
// The divergence is the difference form over the fluid neighbours; the wall's share of it is
// what the Neumann condition imposes (ppe_wall_condition.cpp), except with dynamic walls, where
// the wall's own velocity enters the divergence.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {

void subtract_ppe_source(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         const WallConditions& walls, const Vec3& gravity, double alpha, double dt,
                         const PpeRowFlags& flags, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  const double density_scale = alpha * ctx.rho0 / (dt * dt);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    const double u_i[3] = {work.u_star[0][i], work.u_star[1][i], work.u_star[2][i]};
    const double div_u =
        divergence(ctx, list, p, i, u_i, [&](const NeighborPair& q, double u_j[3]) {
          const std::size_t j = q.j;
          if (j < n) {
            for (int a = 0; a < ctx.dim; ++a) u_j[a] = work.u_star[a][j];
          } else if (walls.dynamic) {
            // The wall's velocity plus the normal part of the virtual marker's velocity relative to
            // it (the fluid's, mirrored at the start of the step), with the same body-force
            // increment dt g as the fluid (the wall jump carries g - a_w). The tangential part is
            // left out: beyond the tip of a flow the markers are dry, and their tangential velocity
            // would read as a divergence.
            double marker_un = 0.0;
            for (int a = 0; a < ctx.dim; ++a)
              marker_un +=
                  (work.boundary.marker_velocity[a][j] - p.velocity[a][j]) * p.normal[a][j];
            for (int a = 0; a < ctx.dim; ++a)
              u_j[a] = p.velocity[a][j] + marker_un * p.normal[a][j] + dt * gravity[a];
          } else {
            for (int a = 0; a < ctx.dim; ++a) u_j[a] = u_i[a];  // no share of the divergence
          }
        });
    // Within a kernel support of the free surface the summation density is low only because the
    // support is truncated, not because the fluid expanded: the density-invariance term would
    // read that deficit as an error and pull the surface in. It acts on interior particles only.
    const double density_error =
        flags.touches_surface[row] ? 0.0 : (ctx.rho0 - p.density[i]) / ctx.rho0;
    work.rhs[row] -= ctx.rho0 / dt * div_u + density_scale * density_error;
  }
}

}  // namespace washout
