// Step 2 of METHOD.md, the stabilized pressure Poisson equation (Asai et al. 2012):
//   <lap P>_i = (rho0/dt) <div u*>_i + alpha (rho0 - <rho>_i) / dt^2
// Unknowns are the fluid particles that are not on the free surface (those take P = 0) nor in a
// squeeze film (those take work.film_pressure, squeeze_film.hpp).
// With the laplacian written as <lap P>_i = -sum_j c_ij (P_i - P_j), c_ij >= 0, every row reads
//   sum_j c_ij (P_i - P_j) = -b_i,
// a symmetric positive definite system when particle volumes are equal.
// Walls enter through the Neumann condition dP/dn = (rho0/dt)(u* - u_wall).n: boundary particle
// w contributes c_iw (P_i - P_w) with P_w = P_i + g_iw (wall_pressure_jump), a known term that
// moves to the right-hand side, so the matrix stays symmetric. The divergence uses fluid
// neighbours only; the wall's share of it is what the Neumann term imposes.
// The assembly is composed of one part per term (pressure_poisson_parts.hpp): the unknowns, the
// matrix (ppe_matrix.cpp), the walls (ppe_wall_condition.cpp), the source (ppe_source.cpp) and
// the pressure level of closed regions (ppe_null_space.cpp).
//
// Free surface, ghost form (default): P = 0 holds at the surface itself, d0/2 beyond the centres
// of the surface particles, not on them. A surface particle i is an unknown; the neighbours its
// support is missing (air) are ghosts whose pressure is the linear extrapolation through P_i
// that vanishes at d0/2 along the outward normal n: P_k = P_i (1 - 2 (r_k . n) / d0). Their
// share of the laplacian, sum_k c_ik (P_i - P_k) = P_i (2/d0) sum_k c_ik (r_k . n), needs only
// the first moment of the missing weights, and on a full lattice sum_k c_ik r_k = 0, so
//   m_i = sum_missing c_ik r_k = - sum_present c_ij (x_j - x_i),   n = m_i / |m_i|,
// and the row gains the diagonal term 2 |m_i| / d0: symmetric and positive, no extra unknowns.
// Imposing P = 0 on the particles themselves (surface_pressure = "on_particles") puts the
// surface half a spacing too low: a hydrostatic error of d0/(2H) and floating bodies too deep.
#include "engine/fluid/isph_stages.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {

std::size_t number_pressure_unknowns(const Particles& p, bool ghost_surface, bool stable_rows,
                                     FluidWork& work) {
  const std::size_t n = p.fluid_count;
  // A particle whose pressure is given, not solved for: P = 0 on it (an isolated drop, or any
  // surface particle without the ghost form) or the squeeze-film pressure.
  const auto given = [&](std::size_t i) {
    return work.boundary.in_film(i) || work.free_surface[i] == FluidWork::kIsolated ||
           (!ghost_surface && work.free_surface[i] == FluidWork::kSurface);
  };
  work.unknown.assign(n, -1);
  std::size_t unknowns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (given(i)) continue;
    work.unknown[i] = static_cast<std::int32_t>(stable_rows ? i : unknowns);
    ++unknowns;
  }
  work.matrix.rows = stable_rows ? n : unknowns;
  return unknowns;
}

PpeStatistics assemble_pressure_poisson(const SphContext& ctx, const NeighborList& list,
                                        const Particles& p, const Vec3& gravity, double alpha,
                                        double dt, bool ghost_surface, FluidWork& work,
                                        const WallConditions& walls, bool symmetric_gradient,
                                        bool stable_rows) {
  const std::size_t unknowns = number_pressure_unknowns(p, ghost_surface, stable_rows, work);
  PpeRowFlags flags;
  assemble_ppe_matrix(ctx, list, p, ghost_surface, symmetric_gradient, work, flags);
  add_known_pressures(ctx, list, p, walls, gravity, dt, work);
  subtract_ppe_source(ctx, list, p, walls, gravity, alpha, dt, flags, work);
  PpeStatistics stats;
  stats.unknowns = unknowns;
  stats.nonzeros = work.matrix.nonzeros();
  stats.pinned_components =
      fix_free_pressure_levels(flags.anchored, work.matrix, work.rhs, work.density_rhs);
  return stats;
}

void gather_pressure_guess(const Particles& p, FluidWork& work) {
  work.solution.assign(work.matrix.rows, 0.0);
  for (std::size_t i = 0; i < p.fluid_count; ++i)
    if (work.unknown[i] >= 0) work.solution[work.unknown[i]] = p.pressure[i];
}

void scatter_pressure(const FluidWork& work, Particles& p) {
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < p.fluid_count; ++i)
    p.pressure[i] = work.unknown[i] >= 0       ? work.solution[work.unknown[i]]
                    : work.boundary.in_film(i) ? work.boundary.film_pressure[i]
                                               : 0.0;
}

}  // namespace washout
