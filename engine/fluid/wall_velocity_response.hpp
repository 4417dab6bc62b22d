#pragma once
// How the right-hand side of the PPE (pressure_poisson.cpp, wall_pressure = "dynamic") changes
// with the rigid velocity of each dynamic body. The PPE sees a body's new velocity only through
// the wall jump of its particles w, P_w = P_i + rho0 [g . r - (a_w . n)(r . n)], r = x_w - x_i,
// with the wall's acceleration a_w = (u_w - u_w^n) / dt; the divergence's wall share uses the
// virtual markers of the start of the step and does not change. u_w = T + w x (x_w - X) is
// linear in the body velocity xi = (T, w), so
//   rhs = rhs(xi^n) + sum_k B_k (xi - xi^n)_k,   d rhs_i / d u_w = (rho0/dt) c_iw n (n . d_iw),
// d_iw = x_i - x_w.
// Column B_k is what this computes; with S_k = A^-1 B_k the pressure and the bodies can be
// solved together (engine/sim/implicit_body_coupling.hpp).
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/fluid/fluid_work.hpp"

namespace washout {

// first_column[b]: the first of body b's dofs_per_body columns (T_x, T_y[, T_z], then w_z in 2D
// or w_x, w_y, w_z in 3D), or -1 for a body that is not solved for. centre[b]: its X.
// columns must hold (number of columns) vectors; each is resized to the PPE's rows and filled.
// `rows` lists the fluid particles (ascending) that may have a body particle in their support:
// only their neighbours are walked (the rest of the fluid, most of it, has zero rows).
void assemble_wall_velocity_response(const SphContext& ctx, const NeighborList& list,
                                     const Particles& p, const FluidWork& work,
                                     std::span<const int> first_column,
                                     std::span<const Vec3> centre, double dt,
                                     std::span<const std::uint32_t> rows,
                                     std::vector<std::vector<double>>& columns);

// The fluid particles within the kernel's support (2h) of some particle of a body b with
// first_column[b] >= 0, ascending: the rows assemble_wall_velocity_response needs.
void fluid_beside_bodies(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                         std::span<const int> first_column, std::vector<std::uint8_t>& mark,
                         std::vector<std::uint32_t>& rows);

}  // namespace washout
