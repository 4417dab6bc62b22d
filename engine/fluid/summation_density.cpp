// Density by summation, METHOD.md "SPH operators": <rho>_i = sum_j m_j W_ij.
#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

// The density walk; with kMoment it also sums each fluid particle's gradient moment into
// `moment` (gradient_scale.cpp), the one walk over the pairs' distances serving both.
template <bool kMoment>
void density_walk(const SphContext& ctx, const NeighborList& list, Particles& p, bool own_kernel,
                  std::vector<double>* moment) {
  const double self = ctx.mass * ctx.kernel.value(0.0);
  const double scale = ctx.rho0 / ctx.full_support_density;
  const std::size_t n = list.size();  // the step lists the fluid; a test may list walls too
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double sum = self, m = 0.0;
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      sum += ctx.mass * ctx.kernel.value(q.r);
      if constexpr (kMoment) m -= gradient_moment_weight(ctx, own_kernel, q.r) * q.r2;
    });
    p.density[i] = sum * scale;
    if constexpr (kMoment)
      if (i < p.fluid_count) (*moment)[i] = m / ctx.dim;
  }
}

}  // namespace

void compute_summation_density(const SphContext& ctx, const NeighborList& list, Particles& p) {
  density_walk<false>(ctx, list, p, false, nullptr);
}

void compute_summation_density_and_gradient_moment(const SphContext& ctx, const NeighborList& list,
                                                   Particles& p, bool symmetric, FluidWork& work) {
  work.gradient_moment.resize(p.fluid_count);
  density_walk<true>(ctx, list, p, symmetric && ctx.symmetric_has_own_kernel(),
                     &work.gradient_moment);
}

}  // namespace washout
