#pragma once
// Slip / no-slip walls by virtual markers (Asai et al. 2013, METHOD.md "Walls"). Each boundary
// particle w looks at its mirror point m = x_w + 2 d_w n_w across the wall surface, interpolates
// the fluid there, and takes the mirrored value:
//   velocity: normal part reversed (no penetration), tangential part times (2 s - 1), relative
//             to the wall's own velocity, with s the slip ratio (0 no-slip, 1 free-slip). The
//             velocity then varies linearly through the surface, where it is s times the fluid's.
//   pressure: P_m + rho0 g . (x_w - x_m), the hydrostatic extrapolation (output, body loads).
#include <vector>

#include "engine/boundary/boundary_state.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {

// Marks the boundary particles that some fluid particle sees (the only ones worth updating) and
// returns how many there are.
std::size_t mark_active_boundary(const NeighborList& list, const Particles& p,
                                 std::vector<std::uint8_t>& active);

// The same marks at the particles' current positions, from a grid built on them (the lists are
// the step's: the fluid has moved since): the boundary particles closer than 2h to some fluid.
void mark_boundary_near_fluid(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                              std::vector<std::uint8_t>& active);

void update_marker_velocities(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                              const std::vector<std::uint8_t>& active, const WallConditions& walls,
                              BoundaryWork& work);

void update_wall_pressures(const SphContext& ctx, const NeighborGrid& grid, const Vec3& gravity,
                           const std::vector<std::uint8_t>& active, Particles& p);

}  // namespace washout
