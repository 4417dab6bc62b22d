// Fickian particle shifting (Lind, Xu, Stansby & Rogers 2012, J. Comput. Phys. 231): after the
// position update, each fluid particle moves down the gradient of the particle concentration,
//   delta r_i = -A h^2 <grad C>_i,   <grad C>_i = sum_j V_j grad W_ij,
// which keeps the particle distribution close to uniform. Within a kernel support of the free
// surface the concentration gradient mostly measures the truncated support and points out of the
// fluid, so only its part tangential to the surface is applied there; beside a wall or a body,
// likewise only its part along the solid's surface.
// Not part of METHOD.md's projection step: an optional stabiliser (parameter shifting = A).
#include <limits>

#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void shift_particles(const SphContext& ctx, const NeighborList& list, Particles& p,
                     const FluidWork& work, double coefficient, double speed_coefficient, double dt,
                     std::vector<double>& scratch) {
  const std::size_t n = p.fluid_count;
  scratch.assign(3 * n, 0.0);
  const double lattice = ctx.volume * ctx.gradient_correction;
  const double max_shift = 0.1 * ctx.d0;  // never more than a tenth of the spacing per step
  with_dimension(ctx.dim, [&](auto dim) {
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double grad[3] = {0, 0, 0};
      bool near_surface = work.free_surface[i] != 0;
      std::size_t nearest_solid = 0;  // nearest boundary particle (0: none)
      double nearest_r = std::numeric_limits<double>::max();
      for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
        near_surface = near_surface || (q.j < n && work.free_surface[q.j]);
        if (q.j >= n && q.r < nearest_r) nearest_r = q.r, nearest_solid = q.j;
        const double f = ctx.kernel.derivative_over_r(q.r);
        for (int a = 0; a < dim; ++a) grad[a] += f * q.d[a];
      });
      // D = A h^2 (fixed) + A_u h |u_i| dt (Skillen et al. 2013: in proportion to the distance
      // the particle moved, so still water is left alone).
      double speed2 = 0.0;
      for (int a = 0; a < dim; ++a) speed2 += p.velocity[a][i] * p.velocity[a][i];
      const double scale = lattice * (coefficient * ctx.h * ctx.h +
                                      speed_coefficient * ctx.h * std::sqrt(speed2) * dt);
      double shift[3] = {0, 0, 0}, norm2 = 0.0;
      for (int a = 0; a < dim; ++a) {
        shift[a] = -scale * grad[a];
        norm2 += grad[a] * grad[a];
      }
      if (near_surface && norm2 > 0) {
        // Remove the part along the surface normal n = -grad C / |grad C|.
        double along = 0.0;
        for (int a = 0; a < dim; ++a) along += shift[a] * grad[a];
        for (int a = 0; a < dim; ++a) shift[a] -= along * grad[a] / norm2;
      }
      if (nearest_solid != 0) {
        // Beside a wall or a body only along its surface: a lattice-made body surface is a
        // staircase whose steps the concentration gradient would keep filling (a fixed disc's
        // pressure load was 45 % off at radius / d0 = 5 without this).
        double along = 0.0;
        for (int a = 0; a < dim; ++a) along += shift[a] * p.normal[a][nearest_solid];
        for (int a = 0; a < dim; ++a) shift[a] -= along * p.normal[a][nearest_solid];
      }
      double s2 = 0.0;
      for (int a = 0; a < dim; ++a) s2 += shift[a] * shift[a];
      const double limit = s2 > max_shift * max_shift ? max_shift / std::sqrt(s2) : 1.0;
      for (int a = 0; a < dim; ++a) scratch[3 * i + a] = limit * shift[a];
    }
  });
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < ctx.dim; ++a)
      p.position[a][i] = ctx.periodic.wrap(p.position[a][i] + scratch[3 * i + a], a);
}

}  // namespace washout
