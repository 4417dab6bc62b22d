#pragma once
// The squeeze film between a body and another solid (the floor under a sinking box, the pier
// under a falling girder). Once the gap is narrower than two particle spacings it holds a single
// layer of particles, which cannot resolve the film's flow: imposing the body's approach on that
// layer asks the pressure to throw it out sideways at V B / (2 gap), a speed that grows without
// bound as the gap closes (measured: the last layer under a sinking box left at over 25 m/s, and
// the box hovered and bounced on it). The film particles leave the PPE's unknowns: each takes
// the pressure of the resolved fluid beside it, continued hydrostatically (set_film_pressure,
// last step's values, entered as a known value like P = 0 at the free surface), and its wall
// jump carries no acceleration. The film passes the surrounding pressure on to the body but
// neither holds it up nor is thrown out; the DEM contact stops the body. (Film particles kept
// in the PPE with no source threw the water at the gap's mouth out at 26 m/s on landing.)
// What is left of the layer when the gap closes below d0 is moved out of it (free_spot.hpp).
#include <cstddef>

#include "engine/boundary/boundary_state.hpp"
#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {

// Marks work.film[i] = 1 for the fluid particles closer than d0 to the surfaces of two different
// solids, one of them a body, whose faces look at each other (normals at more than 120
// degrees): a gap narrower than 2 d0, and the water at its mouth. Returns the number marked.
std::size_t mark_squeeze_film(const SphContext& ctx, const NeighborList& list, const Particles& p,
                              BoundaryWork& work);

// work.film_pressure[i] of each film particle: the mean over its fluid neighbours that are
// neither film nor free surface (free_surface[j] != 0) of P_j + rho0 g.(x_i - x_j), with last
// step's P_j; 0 with none.
void set_film_pressure(const SphContext& ctx, const NeighborList& list, const Particles& p,
                       const Vec3& gravity, const std::vector<std::uint8_t>& free_surface,
                       BoundaryWork& work);

}  // namespace washout
