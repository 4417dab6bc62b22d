#include "engine/sim/body_surface_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/fluid_interpolation.hpp"

namespace washout {

void body_surface_pressure(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           const Vec3& gravity, std::span<const std::uint32_t> particles,
                           std::vector<double>& pressure) {
  const std::size_t count = particles.size();
  pressure.resize(count);
#pragma omp parallel for schedule(dynamic, 64)
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t w = particles[k];
    double m[3], s[3];
    for (int a = 0; a < 3; ++a) {
      const double dn = p.wall_distance[w] * p.normal[a][w];
      s[a] = p.position[a][w] + dn;
      m[a] = p.position[a][w] + 2.0 * dn;
    }
    double sum = 0.0;
    const double fraction = accumulate_fluid_at(ctx, grid, p, m, [&](std::uint32_t f, double W) {
      double d[3] = {s[0] - p.position[0][f], s[1] - p.position[1][f], s[2] - p.position[2][f]};
      if (ctx.periodic.any()) ctx.periodic.minimum_image(d);
      double head = 0.0;
      for (int a = 0; a < ctx.dim; ++a) head += gravity[a] * d[a];
      sum += W * (p.pressure[f] + ctx.rho0 * head);
    });
    double value = 0.0;
    if (fraction >= kDryFluidFraction) {
      value = sum * ctx.volume / fraction;
      if (fraction < kWetFluidFraction) value = std::max(value, 0.0);
    }
    pressure[k] = value;
  }
}

FluidBox fluid_box(const Particles& p) {
  FluidBox box;
  for (int a = 0; a < 3; ++a) {
    const std::vector<double>& x = p.position[a];
    double low = std::numeric_limits<double>::infinity(), high = -low;
#pragma omp parallel for schedule(static) reduction(min : low) reduction(max : high)
    for (std::size_t i = 0; i < p.fluid_count; ++i) {
      if (p.retired(i)) continue;  // in no cell of the grid: no search finds it
      low = std::min(low, x[i]);
      high = std::max(high, x[i]);
    }
    box.lower[a] = low;
    box.upper[a] = high;
  }
  return box;
}

bool beyond_fluid_reach(const SphContext& ctx, const Particles& p, const FluidBox& fluid,
                        std::size_t first, std::size_t count) {
  if (ctx.periodic.any()) return false;
  double lower[3], upper[3], mirror = 0.0;
  for (int a = 0; a < 3; ++a) {
    lower[a] = std::numeric_limits<double>::infinity();
    upper[a] = -lower[a];
  }
  for (std::size_t i = first; i < first + count; ++i) {
    mirror = std::max(mirror, 2.0 * std::abs(p.wall_distance[i]));
    for (int a = 0; a < 3; ++a) {
      lower[a] = std::min(lower[a], p.position[a][i]);
      upper[a] = std::max(upper[a], p.position[a][i]);
    }
  }
  const double reach = 2.0 * ctx.h + mirror + 1e-9;  // 1e-9 m: the rounding of the distances
  for (int a = 0; a < ctx.dim; ++a)
    if (fluid.lower[a] > upper[a] + reach || fluid.upper[a] < lower[a] - reach) return true;
  return false;
}

void build_surface_stencil(const SphContext& ctx, const NeighborGrid& grid, const Particles& p,
                           std::span<const std::uint32_t> particles,
                           std::span<const std::int32_t> unknown, SurfaceStencil& stencil) {
  const std::size_t count = particles.size();
  stencil.offset.assign(count + 1, 0);
  stencil.fraction.resize(count);
  stencil.row.clear();
  stencil.weight.clear();
  // A body's surface has few points beside the fluid's: searched in order, on one thread.
  for (std::size_t k = 0; k < count; ++k) {
    const std::uint32_t w = particles[k];
    double m[3];
    for (int a = 0; a < 3; ++a) m[a] = p.position[a][w] + 2.0 * p.wall_distance[w] * p.normal[a][w];
    const std::size_t first = stencil.row.size();
    const double fraction = accumulate_fluid_at(ctx, grid, p, m, [&](std::uint32_t f, double W) {
      if (unknown[f] < 0) return;
      stencil.row.push_back(unknown[f]);
      stencil.weight.push_back(W);
    });
    if (fraction < kDryFluidFraction) {
      stencil.row.resize(first);
      stencil.weight.resize(first);
    }
    stencil.fraction[k] = fraction < kDryFluidFraction ? 0.0 : fraction;
    stencil.offset[k + 1] = static_cast<std::uint32_t>(stencil.row.size());
  }
}

void stencil_pressure(const SphContext& ctx, const SurfaceStencil& stencil,
                      std::span<const double> rows, std::vector<double>& pressure) {
  const std::size_t count = stencil.fraction.size();
  pressure.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    double sum = 0.0;
    for (std::uint32_t e = stencil.offset[k]; e < stencil.offset[k + 1]; ++e)
      sum += stencil.weight[e] * rows[stencil.row[e]];
    pressure[k] = stencil.fraction[k] > 0.0 ? sum * ctx.volume / stencil.fraction[k] : 0.0;
  }
}

}  // namespace washout
