// Surface velocity smoothing, a stage after the corrector (docs/method.md "Free surface"; not
// in METHOD.md): free-surface particles move with a fraction of their neighbourhood's
// kernel-weighted mean velocity (XSPH, Monaghan 1989, on the surface only). Without it surface
// particles drifted away from the bulk and grew a slosh instability near the walls within 0.5 s.
// The fraction is taken every step, or, as an option, as a rate: set for a step of a reference
// Courant number and compounded for the step actually taken, so that the flow does not depend
// on the step (docs/method.md, twelfth session).
#include <cmath>

#include "engine/fluid/isph_stages.hpp"

namespace washout {

double surface_smoothing_for_step(double fraction_at_reference, double courant,
                                  double reference_courant) {
  if (!(reference_courant > 0.0)) return fraction_at_reference;  // per step
  if (fraction_at_reference <= 0.0 || courant <= 0.0) return 0.0;
  // (1 - f)^(C / C_ref): k steps of C_ref / k leave the same share unsmoothed as one of C_ref.
  return 1.0 - std::pow(1.0 - fraction_at_reference, courant / reference_courant);
}

void smooth_surface_velocity(const SphContext& ctx, const NeighborList& list, Particles& p,
                             const FluidWork& work, double surface_smoothing,
                             std::vector<double>& smoothed) {
  const std::size_t n = p.fluid_count;
  smoothed.assign(3 * n, 0.0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!work.free_surface[i]) continue;
    double sum_w = ctx.kernel.value(0.0), mean[3];
    for (int a = 0; a < 3; ++a) mean[a] = sum_w * p.velocity[a][i];
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
      const std::size_t j = list.index[k];
      if (j >= n) continue;
      double d[3];
      ctx.displacement(p, i, j, d);
      const double w = ctx.kernel.value(std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
      sum_w += w;
      for (int a = 0; a < 3; ++a) mean[a] += w * p.velocity[a][j];
    }
    for (int a = 0; a < 3; ++a)
      smoothed[3 * i + a] =
          p.velocity[a][i] + surface_smoothing * (mean[a] / sum_w - p.velocity[a][i]);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (work.free_surface[i])
      for (int a = 0; a < ctx.dim; ++a) p.velocity[a][i] = smoothed[3 * i + a];
}

}  // namespace washout
