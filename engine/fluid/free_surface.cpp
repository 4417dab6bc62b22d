// Free-surface detection by a density threshold (METHOD.md step 2, "choose"): a particle whose
// kernel support is partly empty has a low summation density. P = 0 holds d0/2 beyond such a
// particle (ghost form, pressure_poisson.cpp) or on it (surface_pressure = "on_particles").
// With h = 1.2 d0 the top particle layer of still water sits near 0.75-0.83 rho0 and the layer
// below near 0.95-0.97 rho0: the default threshold 0.9 keeps them well apart (0.95 made the
// second layer flicker between surface and interior).
// A particle with no fluid neighbour (a drop, or one left in the closing gap between a body and
// the floor) has no pressure equation of its own, whatever its density: it takes P = 0
// (kIsolated).
// The density measures an empty support only while particles keep their spacing: a few
// particles of spray squeezed together (0.3 d0 apart) sum to rho0 or more with three or four
// neighbours. As interior particles their block of the PPE hangs on one or two weak links to
// the surface, and its source (their compression over dt^2) drove them to 1.7e6 Pa and 160 m/s
// in one step (2D wash-out at d0 = 0.0075 m, t = 0.80 s). So a support holding fewer than a
// third of a full one's particles, fluid and wall together (6 of 20 in 2D, 18 of 56 in 3D), also
// makes a surface particle. A still surface's top layer holds 60 % of them; a film's tip on the
// floor 45 % (half was tried: it flagged such tips near rho = 0.9 rho0 too and moved the 2D dam
// break at a/20 enough to gain energy at 0.28 s).
#include "engine/fluid/isph_stages.hpp"

namespace washout {

std::size_t detect_free_surface(const SphContext& ctx, const NeighborList& list, const Particles& p,
                                double threshold, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  work.free_surface.assign(n, 0);
  std::size_t count = 0;
  const std::uint64_t sparse = static_cast<std::uint64_t>(ctx.full_support_neighbours) / 3;
#pragma omp parallel for reduction(+ : count) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    bool alone = true;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1] && alone; ++k)
      alone = list.index[k] >= n;
    const bool thin = list.offset[i + 1] - list.offset[i] < sparse;
    if (alone || thin || p.density[i] < threshold * ctx.rho0) {
      work.free_surface[i] = alone ? FluidWork::kIsolated : FluidWork::kSurface;
      ++count;
    }
  }
  return count;
}

}  // namespace washout
