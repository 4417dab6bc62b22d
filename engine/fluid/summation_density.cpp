// Density by summation, METHOD.md "SPH operators": <rho>_i = sum_j m_j W_ij.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void compute_summation_density(const SphContext& ctx, const NeighborList& list, Particles& p) {
  const double self = ctx.mass * ctx.kernel.value(0.0);
  const double scale = ctx.rho0 / ctx.full_support_density;
  const std::size_t n = list.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double sum = self;
    for_each_neighbor(ctx, list, p, i,
                      [&](const NeighborPair& q) { sum += ctx.mass * ctx.kernel.value(q.r); });
    p.density[i] = sum * scale;
  }
}

void compute_summation_density_and_gradient_moment(const SphContext& ctx, const NeighborList& list,
                                                   Particles& p, bool symmetric, FluidWork& work) {
  const double self = ctx.mass * ctx.kernel.value(0.0);
  const double scale = ctx.rho0 / ctx.full_support_density;
  const bool own_kernel = symmetric && ctx.symmetric_has_own_kernel();
  const std::size_t n = list.size();  // the step lists the fluid; a test may list walls too
  work.gradient_moment.resize(p.fluid_count);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double sum = self, moment = 0.0;
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      sum += ctx.mass * ctx.kernel.value(q.r);
      moment -= gradient_moment_weight(ctx, own_kernel, q.r) * q.r2;
    });
    p.density[i] = sum * scale;
    if (i < p.fluid_count) work.gradient_moment[i] = moment / ctx.dim;
  }
}

}  // namespace washout
