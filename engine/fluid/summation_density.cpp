// Density by summation, METHOD.md "SPH operators": <rho>_i = sum_j m_j W_ij.
#include "engine/fluid/isph_stages.hpp"

namespace washout {

void compute_summation_density(const SphContext& ctx, const NeighborList& list, Particles& p) {
  const double self = ctx.mass * ctx.kernel.value(0.0);
  const double scale = ctx.rho0 / ctx.full_support_density;
  const std::size_t n = list.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double sum = self;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      double d[3];
      ctx.displacement(p, i, list.index[k], d);
      sum += ctx.mass * ctx.kernel.value(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    }
    p.density[i] = sum * scale;
  }
}

}  // namespace washout
