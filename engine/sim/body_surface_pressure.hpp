#pragma once
// The fluid pressure on a body's surface, for the hydrodynamic load F_f = sum -P_i n_i dS_i
// (METHOD.md Rigid bodies). A surface particle w sits at depth d_w below the surface, so its own
// (virtual-marker) pressure would miss the last d_w of head: the buoyancy of a box would come
// out short by d0/height (docs/rigid_bodies.md). The pressure is instead taken on the surface
// point s = x_w + d_w n_w, from the fluid around the mirror point m = x_w + 2 d_w n_w:
//   P(s) = sum_f W(m - x_f) [P_f + rho0 g . (s - x_f)] / sum_f W(m - x_f),
// each fluid particle's pressure carried to s by the hydrostatic gradient. This is exact for a
// fluid at rest however the kernel support is cut by the body or the free surface, and keeps
// the Shepard interpolation's accuracy where the flow adds a dynamic pressure. Dry points (fluid
// fraction below kDryFluidFraction) take P = 0; points at the free surface (fraction below
// kWetFluidFraction) take no negative pressure, which the hydrostatic carry would give above
// the water line.
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"

namespace washout {

// pressure[k] = P(s) for boundary particle particles[k]; the grid must hold the fluid at the
// positions the pressure was solved for.
void body_surface_pressure(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           const Vec3& gravity, std::span<const std::uint32_t> particles,
                           std::vector<double>& pressure);

// The bounding box of the fluid the searches can find (retired particles left out), [lower,
// upper] per axis (empty: lower > upper).
struct FluidBox {
  double lower[3], upper[3];
};
FluidBox fluid_box(const Particles& p);

// True when no fluid particle can be in reach of body particles [first, first + count): within
// 2h of a particle (the PPE's neighbours, the fluid beside a body) or of its mirror point
// x + 2 d n (the surface pressure's search). Their box widened by 2h + max |2 d| and the fluid's
// box are apart; never true in a periodic domain (the boxes would need the images). Such a body
// (the girder before the wave) has a zero surface pressure and zero responses without a search.
bool beyond_fluid_reach(const SphContext& ctx, const Particles& p, const FluidBox& fluid,
                        std::size_t first, std::size_t count);

// The same interpolation as a linear map of the pressure on the PPE's unknowns, without the
// hydrostatic carry and the free-surface clamp: what a pressure response field or a change of
// the pressure gives (the body coupling evaluates it seven times or more a step, so the fluid
// around each surface point is searched once). Fluid that is no unknown (free surface, films)
// contributes zero, as its pressure does to such a change.
struct SurfaceStencil {
  std::vector<std::uint32_t> offset{0};  // surface point k's entries at [offset[k], offset[k+1])
  std::vector<std::int32_t> row;         // the PPE unknown of each fluid particle
  std::vector<double> weight;            // W(m - x_f)
  std::vector<double> fraction;          // per surface point: its fluid fraction (0: dry)
};

// `unknown` maps a fluid particle to its PPE row (-1: none).
void build_surface_stencil(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           std::span<const std::uint32_t> particles,
                           std::span<const std::int32_t> unknown, SurfaceStencil& stencil);

// pressure[k] = P(s_k) of the field given on the PPE's rows.
void stencil_pressure(const SphContext& ctx, const SurfaceStencil& stencil,
                      std::span<const double> rows, std::vector<double>& pressure);

}  // namespace washout
