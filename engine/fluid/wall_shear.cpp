// Wall shear by a wall function (the under-resolved boundary layer of a fixed wall).
//
// Why: with water's viscosity the resolved viscous stress at a wall is nu u / y with y ~ d0/2,
// so the no-slip condition carried by the virtual markers never reaches the flow at SPH
// resolutions (the viscous time d0^2 / nu is tens of seconds): the first particle layer of a
// dam-break surge glides on the floor as on ice, the tip thins to a film one particle thick, and
// the finer the spacing, the further that film runs. A real wall holds a thin turbulent boundary
// layer whose stress follows the smooth-wall law of the wall,
//   u_t / u_* = y+            (y+ = y u_* / nu < 11.06, viscous sublayer)
//   u_t / u_* = ln(y+) / kappa + B   (kappa = 0.41, B = 5.2, log layer),
// with tau_w = rho0 u_*^2. The particles of the first fluid layer (0 < y <= d0 from the wall
// surface; one particle per wall area d0^(dim-1) on a lattice) carry the stress that the markers
// do not: each loses (tau_w - rho0 nu u_t / y) / (rho0 d0) of tangential acceleration, scaled by
// (1 - s) for the wall's slip ratio s (1: free slip, no stress). In the viscous sublayer the
// excess is zero, so laminar flows (Poiseuille) keep their resolved viscous solution. The
// update is capped so that it never reverses the tangential velocity.
// Only fixed and moving walls: a body's load is the pressure on its surface (METHOD.md).
#include <algorithm>
#include <cmath>

#include "engine/fluid/isph_stages.hpp"

namespace washout {

double friction_velocity(double u_t, double y, double nu) {
  constexpr double kappa = 0.41, B = 5.2, sublayer = 11.06;
  if (!(u_t > 0) || !(y > 0)) return 0.0;
  double u_star = std::sqrt(nu * u_t / y);  // the viscous sublayer
  if (y * u_star / nu <= sublayer) return u_star;
  for (int k = 0; k < 30; ++k) {  // fixed point of u* = u_t / (ln(y u*/nu)/kappa + B)
    const double next = u_t / (std::log(y * u_star / nu) / kappa + B);
    if (std::abs(next - u_star) <= 1e-10 * u_star) return next;
    u_star = next;
  }
  return u_star;
}

void apply_wall_shear(const SphContext& ctx, const NeighborList& list, const Particles& p,
                      const WallConditions& walls, double viscosity, double dt, FluidWork& work) {
  const std::size_t n = p.fluid_count;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    // The nearest wall particle gives the wall's surface: its plane, velocity and slip.
    const std::size_t nearest = nearest_boundary(ctx, list, p, i, /*skip_bodies=*/true).index;
    if (nearest == p.size()) continue;
    const double slip = walls.slip[nearest - n];
    if (slip >= 1.0) continue;
    double d[3];
    ctx.displacement(p, i, nearest, d);
    double y = -p.wall_distance[nearest];
    for (int a = 0; a < ctx.dim; ++a) y += d[a] * p.normal[a][nearest];
    if (y > ctx.d0) continue;        // not in the first fluid layer
    y = std::max(y, 0.25 * ctx.d0);  // a particle pressed into the wall layer
    double rel[3] = {0, 0, 0}, un = 0.0;
    for (int a = 0; a < ctx.dim; ++a) {
      rel[a] = work.u_star[a][i] - p.velocity[a][nearest];
      un += rel[a] * p.normal[a][nearest];
    }
    double u_t2 = 0.0;
    for (int a = 0; a < ctx.dim; ++a) {
      rel[a] -= un * p.normal[a][nearest];
      u_t2 += rel[a] * rel[a];
    }
    const double u_t = std::sqrt(u_t2);
    const double u_star = friction_velocity(u_t, y, viscosity);
    const double excess = std::max(0.0, u_star * u_star - viscosity * u_t / y);  // tau/rho0
    if (!(excess > 0)) continue;
    const double loss = std::min(u_t, (1.0 - slip) * dt * excess / ctx.d0);
    for (int a = 0; a < ctx.dim; ++a) work.u_star[a][i] -= loss * rel[a] / u_t;
  }
}

}  // namespace washout
