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

}  // namespace washout
