// density_kick = "positions": the density term of the stabilized PPE (METHOD.md step 2,
//   alpha (rho0 - <rho>_i) / dt^2) moves the particles but is not kept in their velocity.
// With the paper's form the term's pressure gradient stays in u^{n+1}; alpha per unit time
// (docs/method.md, thirty-fourth session) makes that velocity kick the same size every step,
// whatever dt, and the next projection takes most of it back out but not all (a discrete
// divergence of a discrete gradient is not the discrete laplacian), so the kicks of many short
// steps add up: a 2D tank ten particles deep churned at 67 mm/s after 10 s at the default step
// and 52 mm/s at 0.5 ms (docs/stability.md, forty-sixth session). Here the PPE is solved as
// before; the density term's share of the right-hand side alone is solved again, loosely
// (kDensityKickTolerance), for its pressure P_d; the corrector takes the gradient of P - P_d
// and of P, the particles move with the latter, and the difference, the kick, is taken back out
// of the velocity after the move. The pressure written is P - P_d, the divergence-free part's.
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void scatter_density_pressure(const FluidWork& work, std::size_t fluid_count,
                              std::vector<double>& pressure) {
  pressure.assign(fluid_count, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < fluid_count; ++i)
    if (work.unknown[i] >= 0) pressure[i] = work.density_solution[work.unknown[i]];
}

void correct_velocity_keeping_density_kick(const SphContext& ctx, const NeighborList& list,
                                           Particles& p, FluidWork& work,
                                           const WallConditions& walls, const Vec3& gravity,
                                           double dt, const GradientForms& forms) {
  const std::size_t n = p.fluid_count;
  // The gradient is affine in P (the wall's virtual pressure is P_i plus a known jump), so the
  // difference of the two corrections is the density pressure's share alone.
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p.pressure[i] -= work.density_pressure[i];
  correct_velocity(ctx, list, p, work, walls, gravity, dt, forms);
  for (int a = 0; a < 3; ++a)
    work.density_kick[a].assign(p.velocity[a].begin(), p.velocity[a].begin() + n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) p.pressure[i] += work.density_pressure[i];
  correct_velocity(ctx, list, p, work, walls, gravity, dt, forms);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < ctx.dim; ++a)
      work.density_kick[a][i] = p.velocity[a][i] - work.density_kick[a][i];
    p.pressure[i] -= work.density_pressure[i];  // written: the divergence-free part's
  }
}

void remove_density_kick(const FluidWork& work, Particles& p) {
  const std::size_t n = p.fluid_count;
  const int dim = p.dim;
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.retired(i)) continue;
    for (int a = 0; a < dim; ++a) p.velocity[a][i] -= work.density_kick[a][i];
  }
}

}  // namespace washout
