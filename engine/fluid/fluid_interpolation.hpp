#pragma once
// Shepard interpolation of fluid quantities at an arbitrary point (virtual-marker mirror points,
// probes): f(m) = sum_f W(m - x_f) f_f / sum_f W(m - x_f), over fluid particles only.
#include <cmath>

#include "engine/core/neighbor_grid.hpp"
#include "engine/fluid/sph_context.hpp"

namespace washout {

// Calls accumulate(f, W) for each fluid particle f near m; returns sum_f V W, the kernel-weighted
// fluid volume fraction at m (about 1 inside the fluid, 0 where it is dry).
template <class Accumulate>
double accumulate_fluid_at(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           const double m[3], Accumulate&& accumulate) {
  const double r2max = 4.0 * ctx.h * ctx.h;
  double weight_sum = 0.0;
  grid.for_each_candidate(m, [&](std::uint32_t f) {
    if (f >= p.fluid_count) return;
    double d[3] = {m[0] - p.position[0][f], m[1] - p.position[1][f], m[2] - p.position[2][f]};
    if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
    const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (r2 >= r2max) return;
    const double w = ctx.kernel.value(std::sqrt(r2));
    weight_sum += w;
    accumulate(f, w);
  });
  return weight_sum * ctx.volume;
}

// Below this fluid fraction a point is dry: interpolated values there are not trusted.
constexpr double kDryFluidFraction = 0.05;
// A boundary particle whose mirror point holds less than this fluid fraction stands above the
// free surface: it takes no part in the pressure equation (it faces air, not water).
constexpr double kWetFluidFraction = 0.5;

}  // namespace washout
