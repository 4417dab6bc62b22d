// The walls' share of the PPE (METHOD.md step 2 with the virtual markers): a boundary particle w
// enters row i through its virtual pressure P_w = P_i + g_iw (wall_pressure_jump, the Neumann
// condition dP/dn = (rho0/dt)(u* - u_wall).n, or with dynamic walls rho0 (g - a_wall).n), so its
// term c_iw (P_i - P_w) = -c_iw g_iw is known and moves to the right-hand side: the matrix stays
// symmetric. A squeeze-film neighbour's given pressure enters the same way.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"
#include "engine/fluid/pressure_poisson_parts.hpp"

namespace washout {

void add_known_pressures(const SphContext& ctx, const NeighborList& list, const Particles& p,
                         const WallConditions& walls, const Vec3& gravity, double dt,
                         FluidWork& work) {
  const std::size_t n = p.fluid_count;
  work.rhs.assign(work.matrix.rows, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    double known = 0.0;
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      const double c = -ctx.laplacian_weight(q.r, q.r2);
      if (q.j >= n)
        known += c * wall_pressure_jump(ctx, p, work, walls, gravity, i, q.j, q.d, dt);
      else if (work.unknown[q.j] < 0 && work.boundary.in_film(q.j))
        known += c * work.boundary.film_pressure[q.j];
    });
    work.rhs[row] = known;
  }
}

}  // namespace washout
