// The walls' share of the PPE (METHOD.md step 2 with the virtual markers): a boundary particle w
// enters row i through its virtual pressure P_w = P_i + g_iw (wall_pressure_jump, the Neumann
// condition dP/dn = (rho0/dt)(u* - u_wall).n, or with dynamic walls rho0 (g - a_wall).n), so its
// term c_iw (P_i - P_w) = -c_iw g_iw is known and moves to the right-hand side: the matrix stays
// symmetric. A squeeze-film neighbour's given pressure enters the same way.
#include <cmath>

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
    // Most neighbours are fluid particles solved for, which add nothing here: they are passed
    // over before their distance is taken.
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      const bool film = j < n && work.unknown[j] < 0 && work.boundary.in_film(j);
      if (j < n && !film) continue;
      double d[3];
      ctx.displacement(p, i, j, d);
      const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      const double c = -ctx.laplacian_weight(std::sqrt(r2), r2);
      known += c * (film ? work.boundary.film_pressure[j]
                         : wall_pressure_jump(ctx, p, work, walls, gravity, i, j, d, dt));
    }
    work.rhs[row] = known;
  }
}

}  // namespace washout
