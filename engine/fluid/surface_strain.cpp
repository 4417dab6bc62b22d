// The volume error near the free surface, for the density-invariance term of the PPE (METHOD.md
// step 2, alpha (rho0 - <rho>_i) / (rho0 dt^2)). Within a kernel support of the free surface the
// summation density is low because the support is cut, not because the fluid expanded, so it
// cannot measure a volume error there; the term was left out of those rows (ppe_source.cpp), and
// nothing held their volume but the divergence-free projection, whose small inconsistency with
// the corrector's gradient accumulates: in 3D still water the top three layers rose by 0.04 d0 in
// a second and the pressure below fell by 0.5 % of rho g H (docs/method.md, sixteenth session).
// There the volume error is the particle's own accumulated volumetric strain,
//   e_i = sum over the steps it spent there of dt <div u>_i,   (rho0 - <rho>_i) / rho0 ~ e_i,
// with <div u>_i the difference form over all neighbours at the positions the step starts from,
// a wall particle taking the wall's velocity, and u the velocity the particles are about to move
// with. A particle entering the band starts from 0 (the summation density held it until then).
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void accumulate_surface_strain(const SphContext& ctx, const NeighborList& list, const Particles& p,
                               double dt, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  work.surface_strain.resize(n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    bool near_surface = false;
    if (!work.free_surface[i])
      for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1] && !near_surface; ++k)
        near_surface = list.index[k] < n && work.free_surface[list.index[k]] != 0;
    if (!near_surface) {
      work.surface_strain[i] = 0.0;
      continue;
    }
    const double u_i[3] = {p.velocity[0][i], p.velocity[1][i], p.velocity[2][i]};
    const double div = divergence(ctx, list, p, i, u_i, [&](const NeighborPair& q, double u_j[3]) {
      for (int a = 0; a < ctx.dim; ++a) u_j[a] = p.velocity[a][q.j];
    });
    work.surface_strain[i] += dt * div;
  }
}

}  // namespace washout
