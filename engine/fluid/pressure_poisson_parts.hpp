#pragma once
// The parts of the stabilized PPE's assembly (pressure_poisson.cpp composes them), one per term:
// which particles are unknowns, the laplacian's matrix, the walls' Neumann condition, the source,
// and the pressure level of a closed body of fluid. Each row reads
//   sum_j c_ij (P_i - P_j) = -b_i,   b_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2,
// with c_ij = -laplacian_weight >= 0 (see pressure_poisson.cpp for the free surface).
#include <cstdint>
#include <vector>

#include "engine/core/neighbor_grid.hpp"
#include "engine/core/sph_context.hpp"
#include "engine/fluid/fluid_work.hpp"

namespace washout {

// Per row: touches_surface, within a support of the free surface (no density-invariance term
// there); anchored, the row holds a known pressure (a Dirichlet neighbour or its own ghosts), so
// its fluid region's pressure level is fixed.
struct PpeRowFlags {
  std::vector<std::uint8_t> touches_surface, anchored;
};

// Numbers the unknowns in work.unknown (-1: the pressure is given: P = 0 on an isolated drop or,
// without the ghost form, on a surface particle; the film pressure in a squeeze film) and sets
// work.matrix.rows. Returns the number of unknowns. stable_rows: the row of fluid particle i is
// i, and a particle whose pressure is given keeps its row as an identity row (P = 0, decoupled):
// the system's size and order then stay from step to step while drops break off and films form,
// so that a multigrid hierarchy built for an earlier step still fits (pcg_amg's reuse); otherwise
// the rows are the unknowns alone, in particle order.
std::size_t number_pressure_unknowns(const Particles& p, bool ghost_surface, bool stable_rows,
                                     FluidWork& work);

// The matrix: row pattern and laplacian coefficients, -c_ij off the diagonal and sum_j c_ij over
// the fluid neighbours on it (a boundary neighbour's P_w - P_i is known: add_known_pressures),
// plus the ghost surface's 2 |m_i| / d0 and, where the corrector's gradient is the symmetric
// form, its zero-order term's 2 |S_i|^2 (ppe_matrix.cpp). Fills the row flags.
void assemble_ppe_matrix(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         bool ghost_surface, bool symmetric_gradient, FluidWork& work,
                         PpeRowFlags& flags);

// Known pressures on the right-hand side: a boundary neighbour's virtual pressure P_w = P_i +
// g_iw (the Neumann wall condition) gives c_iw g_iw, a squeeze-film neighbour c_ij P_film
// (ppe_wall_condition.cpp). Sets work.rhs.
void add_known_pressures(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         const WallConditions& walls, const Vec3& gravity, double dt,
                         FluidWork& work);

// The source b_i, subtracted from work.rhs (ppe_source.cpp): the velocity divergence of the
// predicted velocity and the density-invariance term, which acts on interior rows only.
void subtract_ppe_source(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         const WallConditions& walls, const Vec3& gravity, double alpha, double dt,
                         const PpeRowFlags& flags, FluidWork& work);

// A closed body of fluid with no free surface (a filled tank, a periodic channel) defines its
// pressure only up to a constant: its right-hand side is made compatible and one value fixed
// (ppe_null_space.cpp). Returns how many such regions were fixed. A second right-hand side for
// the same matrix (the density term's alone, density_kick.cpp), if not empty, is made compatible
// with it.
std::size_t fix_free_pressure_levels(const std::vector<std::uint8_t>& anchored, CsrMatrix& A,
                                     std::vector<double>& rhs, std::vector<double>& second_rhs);

// Whether sweeps in row order carry a flag from the anchored rows to every row along the
// pattern (fix_free_pressure_levels' shortcut): true only when no region is free; false may also
// mean that the sweeps did not get there (a path that winds back and forth through the numbering).
bool every_row_reaches_an_anchor(const std::vector<std::uint8_t>& anchored, const CsrMatrix& A);

}  // namespace washout
